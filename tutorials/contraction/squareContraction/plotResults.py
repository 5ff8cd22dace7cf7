#!/usr/bin/env python3
"""Square contraction tutorial: picture, results table and checks (etc/contractionResults.py);
-chains: those of the variant with FENE chains (chains/: resultsChains.dat, contractionChains.png)."""
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get("DPD_PROJECT_DIR", os.path.join(os.path.dirname(__file__), "../../..")), "etc"))
from contractionResults import main  # noqa: E402

main("Square contraction (docs/scenes.md scene 7)", "-test" in sys.argv[1:], chains="-chains" in sys.argv[1:],
     low_g="-lowG" in sys.argv[1:])
