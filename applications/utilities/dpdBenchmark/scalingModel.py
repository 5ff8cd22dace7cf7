#!/usr/bin/env python3
"""Predicted parallel efficiency of dpdFoamLike on many ranks (docs/parallel.md section 5).

A model with four measured inputs, all from dpdBenchmark on one machine:
  t_p  seconds per particle-step of one rank (dpdBenchmark, 1 rank, 1 thread, 256,000 particles);
  t_g  seconds per ghost particle and step for packing, sending, unpacking and sorting it (the 2-rank
       run's exchange time and extra sort time over its ghosts);
  alpha, beta  one-way latency (s) and bandwidth (bytes/s) of a message (dpdBenchmark -pingpong).

One rank's step on P ranks, N particles at density rho in a cube of side L = (N / rho)^(1/3):
  compute   t_p (N / P) (1 + d),   d = r_c / w for slabs of width w = L / P (the plane of cells below
            the slab, one cutoff wide, is a home plane of both ranks: its pair work is done twice);
            for cubes of edge w = L / P^(1/3), three such faces.
  ghosts    G = 2 rho L^2 r_c per slab (two planes); rho ((w + 2 r_c)^3 - w^3) per cube
  exchange  t_g G + m (alpha + 81 G / (m beta)) with m messages per step: 2 x 2 for slabs (migration
            and ghosts, to two neighbours: as built), 2 x 26 for cubes; or, as first built, all-to-all: 2 P
            messages of which 2 x 2 carry data.
Efficiency (strong scaling) E(P) = t_p N / (P T(P)). Slabs need at least one cell plane (one cutoff)
per rank, and more to pay: where E falls under 50 %, or under the cubes', slabs stop paying.
The measured 2-rank point (weak scaling, 256,000 per rank) is printed beside the model's.
"""
import argparse
import math


def slab_step(N, P, a):
    L = (N / a.rho) ** (1 / 3)
    w = L / P
    if w < a.rc:  # not even one plane of cells per rank
        return None
    d = a.rc / w if P > 1 else 0.0
    G = 2 * a.rho * L * L * a.rc if P > 1 else 0.0
    messages = (2 * P if a.alltoall else 4) if P > 1 else 0
    comm = messages * a.alpha + 81 * G / a.beta
    return a.tp * N / P * (1 + d) + a.tg * G + comm


def cube_step(N, P, a):
    L = (N / a.rho) ** (1 / 3)
    w = L / P ** (1 / 3)
    if w < a.rc:
        return None
    d = 3 * a.rc / w if P > 1 else 0.0
    G = a.rho * ((w + 2 * a.rc) ** 3 - w ** 3) if P > 1 else 0.0
    comm = (52 * a.alpha + 81 * G / a.beta) if P > 1 else 0.0
    return a.tp * N / P * (1 + d) + a.tg * G + comm


def efficiency(step, N, P, a):
    t = step(N, P, a)
    return None if t is None else a.tp * N / (P * t)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--tp", type=float, default=9.1e-8, help="s per particle-step and core, every core of the node busy")
    p.add_argument("--tg", type=float, default=8e-8, help="s per ghost particle and step (exchange, sort, pair inputs)")
    p.add_argument("--alpha", type=float, default=2.9e-7, help="one-way latency, s (this machine: 0.29 us)")
    p.add_argument("--beta", type=float, default=1.0e10, help="bandwidth, bytes/s (this machine: 10 GB/s)")
    p.add_argument("--rho", type=float, default=3.0)
    p.add_argument("--rc", type=float, default=1.0)
    p.add_argument("--alltoall", action="store_true", help="the exchange as first built (all-to-all, 2P messages)")
    p.add_argument("--measured2", type=float, default=None, help="measured weak-scaling efficiency, 2 ranks")
    a = p.parse_args()

    ranks = [8, 16, 32, 64, 128, 256, 512, 1024]
    print(f"# scalingModel: t_p {a.tp:.3g} s, t_g {a.tg:.3g} s, latency {a.alpha:.3g} s, bandwidth {a.beta:.3g} B/s,"
          f" rho {a.rho}, r_c {a.rc}, exchange {'all-to-all' if a.alltoall else 'neighbours only'}")
    # The 2-rank weak-scaling point: 256,000 per rank in a box two cubes long (what dpdBenchmark measures).
    n1 = 256000
    L = (n1 / a.rho) ** (1 / 3)
    G = 2 * a.rho * L * L * a.rc
    t2 = a.tp * n1 * (1 + a.rc / L) + a.tg * G + 4 * a.alpha + 81 * G / a.beta
    line = f"# weak scaling, 2 ranks x 256,000: model {a.tp * n1 / t2:.3f}"
    if a.measured2 is not None:
        line += f", measured {a.measured2:.3f}"
    print(line)
    print("# strong-scaling efficiency E(P) = T(1) / (P T(P)); '-' where a slab (cube) would be under one cutoff")
    print("# N          decomposition " + " ".join(f"{P:>6d}" for P in ranks))
    for N in [1e6, 1e7, 1e8, 1e9]:
        for name, step in (("slabs", slab_step), ("cubes", cube_step)):
            cells = []
            for P in ranks:
                e = efficiency(step, N, P, a)
                cells.append(f"{e:6.2f}" if e is not None else "     -")
            print(f"{N:9.0e}  {name:13s} " + " ".join(cells))
    print("# slabs stop paying (E < 0.5 or below cubes) at:")
    for N in [1e6, 1e7, 1e8, 1e9]:
        stop = None
        for P in [2 ** k for k in range(1, 21)]:
            es, ec = efficiency(slab_step, N, P, a), efficiency(cube_step, N, P, a)
            if es is None or es < 0.5 or (ec is not None and es < ec - 0.05):
                stop = P
                break
        L = (N / a.rho) ** (1 / 3)
        print(f"#   N {N:.0e}: box {L:.0f} cutoffs long; from about {stop} ranks (a slab {L / stop:.1f} cutoffs wide)")


if __name__ == "__main__":
    main()
