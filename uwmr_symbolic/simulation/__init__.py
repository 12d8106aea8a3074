"""Simulation harness: the generated controllers in closed loop with the unicycle (1).

    simulate_design(design_path, report=None, monte_carlo=0, seed=0, ...) -> dict
    render_simulation_text(result) -> str

One run with its trajectories and plots: `uwmr_symbolic.simulate(report,
scenario)` -> `SimulationResult` (`result`).

See `reference` (paths), `controllers` (the generated C and Python),
`loop` (continuous and 100 Hz digital loops, batch), `metrics` (checks),
`paper` (`make paper`) and `figures` (`make figures`)."""
from .api import Scenario, monte_carlo_scenario, paper_scenario, render_simulation_text, simulate_design
from .reference import (Reference, ReferenceError, WrappedHeadingError, circle, from_function, from_path,
                        from_waypoints, lemniscate)

from .result import SimulationResult

__all__ = ["SimulationResult", "simulate_design", "render_simulation_text", "monte_carlo_scenario", "paper_scenario", "Scenario",
           "Reference", "ReferenceError", "WrappedHeadingError", "circle", "lemniscate", "from_function",
           "from_path", "from_waypoints"]
