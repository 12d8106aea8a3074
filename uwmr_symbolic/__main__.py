"""`python -m uwmr_symbolic`: the same command as `uwmr-verify`."""
from .cli import run

if __name__ == "__main__":
    run()
