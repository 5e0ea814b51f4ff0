#!/usr/bin/env python3
"""batch_rows.py N > rows.csv: the calculator's batch benchmark input (docs/performance.md), N rows
of R from 150 to 400 m and m from 30 to 100 kg, drawn uniformly with a fixed seed (some fall
outside the table, as a user's batch does)."""
import random
import sys

count = int(sys.argv[1]) if len(sys.argv) > 1 else 100000
rng = random.Random(1)
out = ["R_m,m_kg"]
for _ in range(count):
    out.append(f"{rng.uniform(150, 400):.6g},{rng.uniform(30, 100):.6g}")
sys.stdout.write("\n".join(out) + "\n")
