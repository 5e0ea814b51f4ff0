#!/usr/bin/env python3
"""shot_designs.py N > designs.json: the verifier's batch benchmark input (docs/benchmarks.md), N
designs drawn uniformly over the ranges of the reference check (tests/test_reference.cpp): l = L1/L2
3.5-7, L4/L1 0.7-1.2, mb/M 0.03-0.15, m/M 0.004-0.02, theta_i 25-45 deg, F 0.5-1, L2 0.3-1.5 m, with
M = 1000 kg and a fixed seed."""
import json
import random
import sys

count = int(sys.argv[1]) if len(sys.argv) > 1 else 1280
rng = random.Random(1)
designs = []
for _ in range(count):
    L2 = rng.uniform(0.3, 1.5)
    L1 = rng.uniform(3.5, 7) * L2
    designs.append({"L1": round(L1, 6), "L2": round(L2, 6), "L4": round(rng.uniform(0.7, 1.2) * L1, 6), "M": 1000,
                    "mb": round(rng.uniform(0.03, 0.15) * 1000, 6), "m": round(rng.uniform(0.004, 0.02) * 1000, 6),
                    "theta_i_deg": round(rng.uniform(25, 45), 6), "F": round(rng.uniform(0.5, 1), 6)})
json.dump(designs, sys.stdout, indent=0)
sys.stdout.write("\n")
