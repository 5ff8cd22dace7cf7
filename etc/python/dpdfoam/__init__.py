"""dpdfoam: the toolkit's post-processing in Python, shared by the tutorials' plotResults.py scripts.

On PYTHONPATH from etc/bashrc (etc/python), so a script imports it without path hacks:

    from dpdfoam.io import latest, read_table
    from dpdfoam.checks import Checks

Modules:
    io          reading what the tools write: profile tables, fit.dat and other dictionaries, runSweep's
                tables, sampled blocks, logs, OpenFOAM fields
    stats       means and standard errors, Student-t quantiles, Welch-Satterthwaite, jackknife
    blocks      a profile's sampled blocks joined into super-blocks (errors of slow flows)
    channel     channel flows: the no-slip Poiseuille profile, kT against the shear rate, the slip of
                the two walls, the particles the walls turn round or let through per unit time and area
    checks      the checks' bookkeeping: pass / fail / information, a NaN or missing value fails
    published   a tutorial's published.dat and the comparison with the paper's tables
    plots       the figures' common parts (Agg backend)
    snapshots   the solver's snapshots: the box, the same particles, the chains' bonds, the chains'
                extension across a channel
    mask        an image mask's regions: solid on the bins, distance to it, pore size, an open band and
                whether a line runs along it
    contraction the contraction tutorials' scene (tutorials/contraction/*)
    pair_temperature  a bulk's kT split into heat and shared motion (etc/pairTemperature.py)
    timeseries  a run's time series (snapshots' measures, logs) as super-block means over fitSlipLength's
                super-blocks (SuperBlockWindow), slopes per super-block, values binned by a position
    channel_blocks  a Poiseuille channel case over fitSlipLength's super-blocks: flux, centre velocity,
                bulk kT and its heat, nu, asymmetry, densities at the walls, the run's log
    grid        a 2-D profile table averaged along one axis, its region means, a column as an image
    slip        tunable-slip and striped walls: gamma_L for a slip length, calibrateWall's runs, slipTensor's
                runs, stripedSlip's reference with its calibration error and the checks against it, a
                stripeGrid's layers over the stripes' sectors
    fields      an x-z grid of bins as arrays, a continuum twin's cells on it, relative L2 (overall and per
                class of pore size or distance to the solid), the bins' kT beside the log's series
    sweep       runSweep's sweeps of a wall parameter (variant, slip, published comparison, trend checks,
                profiles), a profile near its walls, channels compared with long-block errors
    stepstudy   a study of the time step per integrator: cost model, where an error passes a level,
                blow-ups, the largest step that keeps a property, equal accuracy, the pictures
    stepruns    a step study made of whole runs (tutorials/benchmarks/walledStep): its dictionary, each run's nu,
                slip length, kT next to the walls and cost read from its case, the largest step that keeps
                them, the runs' tables and the picture
    lattice_wall  the lattice-wall Poiseuille channel (tutorials/channel/poiseuille/latticeWall): its measures
                against the fluid without walls, lattice and random walls compared with long-block errors
                (no slip, nu, the pairs' agreement), the simpleFoam twin against the analytic parabola
    striped     the striped-wall scene (tutorials/channel/stripedWall): the calibration's choice of gamma_L,
                the slip tensor's studies against the continuum reference (StripedStudy), the pictures
    poiseuille  scene 1 as published (tutorials/channel/poiseuille): each seed's run of the FCC and random
                walls (SeedRun), their means over the seeds, poiseuille.png, the bounce layer's alpha sweep
    couette     the Couette slip scene (tutorials/channel/couetteSlip): the shear stress's flatness, nu
                and kT of the first channel and the slip's growth with a_wf checked, the pictures
    slip_length the slip length as the user's input (tutorials/channel/slipLength): the channel's middle,
                the density peak's errors, slipLength.png
    polymer_channel  FENE chains in a Poiseuille channel (tutorials/polymer/channel): a case's flow, heat,
                beads, chains and the paper's grid (Case), the checks, results<variant>.dat, the pictures
    porous      the porous medium (tutorials/porous/porousMedium): the checks at a tutorial's budgets and
                bounds (PorousChecks), the velocity next to the grains, the pictures

The fits are the C++ tools' (fitSlipLength, compareFVM, slipTensor, hydrodynamicWall, stripedSlip,
chainScaling): the package reads their results (fitSlipLength's superBlocks entry gives the jackknife
errors over super-blocks; chainScaling the power law R_g^2 ~ N^(2 nu)).
"""
