# Every target sets up what it needs: a fresh clone only needs `make demo` or `make test`.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: demo test test-fast docs bench clean generate embedded arm-toolchain paper figures fuzz fuzz-codegen mutate

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e '.[test]'
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/python -m uwmr_symbolic.demo designs

# The whole suite (about 8 min on 2 idle cores), then the Cortex-M check.
test: $(STAMP)
	@if ! command -v cmake >/dev/null 2>&1; then \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "make test: cmake not found; running as root, so installing it with apt-get (for the CMake example test)"; \
	    { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq cmake; } || exit 1; \
	  else \
	    echo "make test: cmake not found, the CMake example test will be skipped (to enable: sudo apt-get install cmake)"; \
	  fi; \
	fi
	@$(MAKE) --no-print-directory arm-toolchain    # before pytest: the Cortex-M tests then run, not skip
	$(BIN)/python -m pytest -q
	$(MAKE) --no-print-directory embedded

# Tests not marked slow (markers in pyproject.toml), on 2 workers: under a minute.
test-fast: $(STAMP)
	$(BIN)/python -m pytest -q -n 2 --dist loadfile -m "not slow and not fuzz"

# API reference from the docstrings and docs/*.md into site/; a warning fails the build.
DOCS_STAMP := $(VENV)/.docs-installed
$(DOCS_STAMP): $(STAMP)
	$(BIN)/pip install --quiet -e '.[docs]'
	touch $(DOCS_STAMP)

docs: $(DOCS_STAMP)
	$(BIN)/mkdocs build --strict --site-dir site

# Controllers for every design (unverified ones with the NOT VERIFIED banner);
# CI: `make generate && git diff --exit-code generated/` fails when stale.
generate: $(STAMP)
	$(BIN)/python -m uwmr_symbolic.codegen --force designs/*.py

# Random proved radial designs through generation and validation (longer than the
# fixed-seed profile of `make test`); prints designs tried / proved / generated.
fuzz-codegen: $(STAMP)
	UWMR_FUZZ_EXAMPLES=$${UWMR_FUZZ_EXAMPLES:-40} UWMR_FUZZ_TIMEOUT=20 UWMR_FUZZ_VERBOSE=1 \
	  $(BIN)/python -m pytest -q -s -p no:cacheprovider tests/test_codegen_fuzz.py

# Cortex-M4F build of the float variants.  When the toolchain is missing: as root
# (CI) it is installed with apt-get, saying so; as any other user the check is
# skipped with a notice (ARM_GCC names the compiler looked for).
ARM_GCC ?= arm-none-eabi-gcc
# The Cortex-M cross-compiler: installed with apt-get when running as root, else a hint.
arm-toolchain:
	@if ! command -v $(ARM_GCC) >/dev/null 2>&1; then \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "$(ARM_GCC) not found; running as root, so installing gcc-arm-none-eabi and libnewlib-arm-none-eabi with apt-get"; \
	    { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq gcc-arm-none-eabi libnewlib-arm-none-eabi; } || exit 1; \
	  else \
	    echo "$(ARM_GCC) not found: the Cortex-M builds are skipped (to enable: sudo apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi)"; \
	  fi; \
	fi

embedded: $(STAMP) arm-toolchain
	@if ! command -v $(ARM_GCC) >/dev/null 2>&1; then echo "make embedded: skipped, $(ARM_GCC) not found"; exit 0; fi; \
	echo "$(BIN)/python -m uwmr_symbolic.codegen.embedded"; \
	$(BIN)/python -m uwmr_symbolic.codegen.embedded

# Long soundness fuzzing: UWMR_FUZZ_EXAMPLES random designs (fresh seed; UWMR_FUZZ_SEED=N repeats one),
# table of verdicts, false proofs and wrong refutations; designs with a contradiction go to fuzz-findings/.
UWMR_FUZZ_EXAMPLES ?= 500
fuzz: $(STAMP)
	cd tests && ../$(BIN)/python -m fuzz.run --examples $(UWMR_FUZZ_EXAMPLES) \
	  $(if $(UWMR_FUZZ_SEED),--seed $(UWMR_FUZZ_SEED)) --keep ../fuzz-findings

bench: $(STAMP)
	$(BIN)/python benchmarks/bench_verify.py
	$(BIN)/python benchmarks/bench_scaling.py
	$(BIN)/python benchmarks/bench_cache.py
	$(BIN)/python benchmarks/bench_certificate.py
	$(BIN)/python benchmarks/kernel_size.py
	$(BIN)/python benchmarks/bench_codegen.py
	$(BIN)/python benchmarks/bench_sim.py

# Section 5 of the paper in simulation: Table 1 in exact arithmetic, Tables 2-3 simulated.
paper: $(STAMP)
	$(BIN)/python -m uwmr_symbolic.simulation.paper

# PNGs in the style of Figures 4-9 into figures/.
figures: $(STAMP)
	$(BIN)/python -m uwmr_symbolic.simulation.figures --out figures

clean:
	rm -rf $(VENV) build *.egg-info fuzz-findings site mutants mutants.log

# Mutation testing of the trusted kernel: mutmut (settings in pyproject.toml) mutates
# uwmr_symbolic/kernel/ and runs the fast kernel tests on each mutant (about 37 min on the
# 2 shared cores; MUTATE_JOBS workers, default 2), then prints killed / total and the
# survivors by function; fails below MUTATE_MIN % killed (default 90).  Equivalent
# survivors: docs/kernel.md, "Mutation testing".
MUT_STAMP := $(VENV)/.mutation-installed
$(MUT_STAMP): $(STAMP)
	$(BIN)/pip install --quiet -e '.[mutation]'
	touch $(MUT_STAMP)

MUTATE_JOBS ?= 2
mutate: $(MUT_STAMP)
	rm -rf mutants
	nice $(BIN)/mutmut run --max-children $(MUTATE_JOBS) > mutants.log 2>&1 || { tail -c 2000 mutants.log; exit 1; }
	@tail -c 300 mutants.log | tr '\r' '\n' | tail -3
	$(BIN)/python tests/kernel_mutation_score.py
