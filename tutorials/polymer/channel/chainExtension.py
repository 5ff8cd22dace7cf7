#!/usr/bin/env python3
"""The chains' extension by where they lie across the channel, from a case's snapshots (polymer channel
tutorial; README, "Chain extension across the channel").

For every snapshot (<time>/particles.h5) in the sampled window of a binnedProfile function (its startTime
to the run's endTime, system/controlDict), every chain unwrapped from its bond vectors gives one row
(dpdfoam.snapshots.write_extension): its centre across the channel (the mean bead coordinate along the
profile's axis), its extension along the flow (x: max - min bead x), its R_g^2 and the square of its
end-to-end vector's x component. chainStatistics bins the same by the chain's centre but keeps no block
errors per bin; from these rows plotResults.py forms super-block means of the outer and the central
chains, with errors. Written whole or not at all:
    postProcessing/chainExtension/<start>/chainExtension.dat   (time chain centre spanx Rg2 Reex2)

    chainExtension.py [-case DIR] [-function NAME (channelProfile)]
"""
import sys

from dpdfoam.snapshots import extension_command

if __name__ == "__main__":
    sys.exit(extension_command(__doc__.splitlines()[0]))
