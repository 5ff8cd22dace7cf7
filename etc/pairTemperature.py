#!/usr/bin/env python3
"""The command of dpdfoam.pair_temperature (docs/analysis.md 5.5): a bulk's kT split into heat and the
motion neighbours share, from a case's snapshots.

    pairTemperature.py [-case DIR] -function NAME [-central FRACTION (0.5)]
"""
import sys

from dpdfoam.pair_temperature import main  # etc/bashrc puts etc/python on PYTHONPATH

if __name__ == "__main__":
    sys.exit(main())
