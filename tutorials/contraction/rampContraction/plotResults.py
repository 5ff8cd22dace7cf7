#!/usr/bin/env python3
"""Ramp contraction tutorial: picture, results table and checks (dpdfoam.contraction, shared with the other
contraction); -chains: those of the variant with FENE chains (chains/: resultsChains.dat, contractionChains.png)."""
import sys

from dpdfoam.contraction import main

main("Ramp contraction (docs/scenes.md scene 7)", sys.argv[1:])
