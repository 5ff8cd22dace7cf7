"""Shared fixtures of the dpdfoam unit tests (tests/python/test_<module>.py): files the tools write,
built by hand in a temporary directory, and a stand-in for the dpdDictionary tool.

Each writer follows the format the C++ side writes (the comments name the writer); the tests build
their inputs from known values and compare the package's results with what those values give.
"""
import contextlib
import os
import stat
import sys
import tempfile
import unittest
from unittest import mock

import numpy as np


def write_text(path, text):
    """text to path, its directories made first; returns path."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)
    return path


def write_table(path, columns):
    """A profileBins-style table: '# name name ...' then one row per bin (columns: {name: values})."""
    names = list(columns)
    rows = np.column_stack([np.asarray(columns[n], dtype=float) for n in names])
    lines = ["# " + " ".join(names)] + [" ".join(repr(float(v)) for v in row) for row in rows]
    return write_text(path, "\n".join(lines) + "\n")


def dictionary_text(entries):
    """`key value;` lines as the tools write fit.dat and compare.dat (lists as '(a b c)')."""
    lines = []
    for key, value in entries.items():
        if isinstance(value, (list, tuple)):
            value = "(" + " ".join(repr(float(v)) for v in value) + ")"
        elif isinstance(value, float):
            value = repr(value)
        lines.append(f"{key} {value};")
    return "\n".join(lines) + "\n"


def write_fit(case, entries, time="100", tool="fitSlipLength"):
    """<case>/postProcessing/<tool>/<time>/fit.dat holding entries."""
    return write_text(os.path.join(case, "postProcessing", tool, time, "fit.dat"), dictionary_text(entries))


def jackknife_fit(m, per, length, **more):
    """fit.dat's entries of a fit with m super-blocks of `per` sampling blocks, each `length` long."""
    entries = {"mode": "poiseuille", "errors": "jackknife", "superBlocks": m, "blocksPerSuperBlock": per,
               "superBlockLength": float(length)}
    entries.update(more)
    return entries


def bin_sums(x, v):
    """The 12 sums of sampling/BinAccumulator.hpp's BinSums for particle-samples at x (along the bin's
    axis) with velocities v (n, 3): count, sum v (3), sum v^2 (3), sum x, sum x^2, sum v x (3)."""
    x, v = np.asarray(x, dtype=float), np.asarray(v, dtype=float)
    return np.concatenate([[len(x)], v.sum(axis=0), (v * v).sum(axis=0), [x.sum(), (x * x).sum()],
                           (v * x[:, None]).sum(axis=0)])


def write_sampling(path, blocks, samples_per_block, lo, hi, block_samples, cross_section, dimension=3):
    """A 1-D binnedProfile's sampled blocks (sampling/BinAccumulatorFile.cpp): dataset blocks (blocks,
    bins, sums), samplesPerBlock, and the attributes the package reads."""
    import h5py

    blocks = np.asarray(blocks, dtype=float)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with h5py.File(path, "w") as f:
        f["blocks"] = blocks
        f["samplesPerBlock"] = np.asarray(samples_per_block, dtype=np.int64)
        f.attrs["format"] = "dpdFoamLike-bins-2"
        f.attrs["nBins"] = blocks.shape[1]
        f.attrs["lo"], f.attrs["hi"] = float(lo), float(hi)
        f.attrs["blockSamples"] = np.int64(block_samples)
        f.attrs["crossSection"] = float(cross_section)
        f.attrs["dimension"] = np.int64(dimension)
    return path


def write_snapshot(path, position, velocity=None, species=None, ids=None, species_names=("fluid",),
                   frozen=(0,), lo=(0, 0, 0), hi=(10, 10, 10), time=0.0, dimension=3, bonds=None):
    """A solver snapshot (io/Snapshot.cpp): particles/position, velocity, id, species, the box, the
    species' names and frozen flags; bonds = (pairs of ids, vectors, chains) when given."""
    import h5py

    position = np.asarray(position, dtype=float)
    n = len(position)
    velocity = np.zeros((n, 3)) if velocity is None else np.asarray(velocity, dtype=float)
    species = np.zeros(n, dtype=np.int64) if species is None else np.asarray(species, dtype=np.int64)
    ids = np.arange(n, dtype=np.uint64) if ids is None else np.asarray(ids, dtype=np.uint64)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with h5py.File(path, "w") as f:
        f["particles/position"], f["particles/velocity"] = position, velocity
        f["particles/id"], f["particles/species"] = ids, species
        f.attrs["time"] = float(time)
        f.attrs["dimension"] = np.int64(dimension)
        f.attrs["boxLo"], f.attrs["boxHi"] = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
        f.attrs["speciesNames"] = [s.encode() for s in species_names]
        f.attrs["speciesFrozen"] = np.asarray(frozen, dtype=np.int64)
        if bonds is not None:
            pairs, vectors, chains = bonds
            f["bonds/pairs"] = np.asarray(pairs, dtype=np.uint64).reshape(-1, 2)
            f["bonds/vector"] = np.asarray(vectors, dtype=float).reshape(-1, 3)
            f["bonds/chain"] = np.asarray(chains, dtype=np.int64)
    return path


def _sh_quote(text):
    return "'" + text.replace("'", "'\\''") + "'"


@contextlib.contextmanager
def fake_dictionary(directory, entries):
    """dpdDictionary on PATH answering `<file> -entry <entry> -value` for entries {(file, entry): value
    text} (files absolute, or relative to the working directory here) with `value;` as the tool prints
    it, failing (exit 1, as the tool does) for any other entry; `<file> -entry <entry> -set <value>` is
    recorded. A shell script, so that a call costs milliseconds. Yields a function returning the -set
    calls made: [(file, entry, value)]."""
    bin_dir = os.path.join(directory, "fake-bin")
    os.makedirs(bin_dir, exist_ok=True)
    calls = os.path.join(bin_dir, "calls.tsv")
    cases = "".join(f"    {_sh_quote(os.path.abspath(p) + '|' + e)}) printf '%s;\\n' {_sh_quote(str(v))} ;;\n"
                    for (p, e), v in entries.items())
    script = ("#!/bin/sh\n"
              "# A stand-in for dpdDictionary (tests/python/dpdtest_support.py).\n"
              'case "$1" in /*) file="$1" ;; *) file="$PWD/$1" ;; esac\n'
              'if [ "$#" -eq 5 ] && [ "$2" = -entry ] && [ "$4" = -set ]; then\n'
              f'    printf \'%s\\t%s\\t%s\\n\' "$file" "$3" "$5" >> {_sh_quote(calls)}\n'
              "    exit 0\n"
              "fi\n"
              'if [ "$#" -ne 4 ] || [ "$2" != -entry ] || [ "$4" != -value ]; then\n'
              '    echo "fake dpdDictionary: unexpected arguments $*" >&2\n'
              "    exit 2\n"
              "fi\n"
              'case "$file|$3" in\n' + cases +
              '    *) echo "dpdDictionary: $1: no entry $3" >&2; exit 1 ;;\n'
              "esac\n")
    tool = os.path.join(bin_dir, "dpdDictionary")
    with open(tool, "w") as f:
        f.write(script)
    os.chmod(tool, os.stat(tool).st_mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)
    with mock.patch.dict(os.environ, {"PATH": bin_dir + os.pathsep + os.environ.get("PATH", "")}):
        yield lambda: set_calls(calls)


def set_calls(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [tuple(line.rstrip("\n").split("\t")) for line in f]


@contextlib.contextmanager
def fake_tool(directory, name, source):
    """An executable `name` on PATH running the Python source (a stand-in for a C++ tool whose output
    format the test reproduces)."""
    bin_dir = os.path.join(directory, "fake-bin-" + name)
    os.makedirs(bin_dir, exist_ok=True)
    tool = os.path.join(bin_dir, name)
    with open(tool, "w") as f:
        f.write(f"#!{sys.executable} -S\n" + source)
    os.chmod(tool, os.stat(tool).st_mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)
    with mock.patch.dict(os.environ, {"PATH": bin_dir + os.pathsep + os.environ.get("PATH", "")}):
        yield tool


@contextlib.contextmanager
def working_directory(path):
    """The working directory set to path for the block (the tutorials' scripts run in their case)."""
    old = os.getcwd()
    os.chdir(path)
    try:
        yield path
    finally:
        os.chdir(old)


# A test case with a temporary directory of its own, removed after each test.
class Temporary(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory()
        self.tmp = self._tmp.name

    def tearDown(self):
        self._tmp.cleanup()

    def path(self, *parts):
        return os.path.join(self.tmp, *parts)
