#!/usr/bin/env python3
"""contest_promises.py VERIFY [SEED] [COUNT]: the contest's promises (docs/machines.md) on COUNT
random contests in vacuum (default 8, seed 1), as a builder would try them. Each contest (a
machine, a ball of 0.5 to 10 kg, a beam of 1 to 10 kg/m, a box of 2-8 m by 2-6 m, a counterweight
of 30 to 150 balls, and by chance a limit on the acceleration or the axle) is run by the program
VERIFY, then once with each limit 10 % looser. It prints each relaxation's gain against the one
claimed, marks one that shortens the range by more than 1e-4 of it (non-monotone) or whose gain is
off by more than 1e-3 of it (untrue), and the counts. Two contests at a time; minutes of CPU. A
measurement (docs/benchmarks.md), not a test: it holds no tolerance of its own."""
import json
import random
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

UNITS = {"max-width": "m", "max-height": "m", "max-M": "kg", "max-acceleration": "", "max-axle-load": "N"}


def random_contests(seed, count):
    rng = random.Random(seed)
    contests = []
    for _ in range(count):
        machine = rng.choice(["hinged", "fixed", "floating-arm"])
        m = rng.choice([0.5, 2, 4, 10])
        beam = rng.choice([1, 3, 6, 10])
        limits = {"max-width": round(rng.uniform(2, 8), 2), "max-height": round(rng.uniform(2, 6), 2), "max-M": round(m * rng.uniform(30, 150))}
        if rng.random() < 0.5:
            limits["max-acceleration"] = round(rng.uniform(150, 800))
        if rng.random() < 0.3:
            limits["max-axle-load"] = round(m * 9.81 * rng.uniform(50, 300))
        contests.append((machine, m, beam, limits))
    return contests


def run(verify, machine, m, beam, limits):
    args = [verify, "contest", "--format", "json", "--machine", machine, "--m", f"{m}kg", "--mb-per-m", str(beam)]
    for key, value in limits.items():
        args += [f"--{key}", f"{value}{UNITS[key]}"]
    out = subprocess.run(args, capture_output=True, text=True)
    try:
        return json.loads(out.stdout)
    except json.JSONDecodeError:
        return {"error": out.stderr.strip()[:100]}


def main():
    verify = sys.argv[1]
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    count = int(sys.argv[3]) if len(sys.argv) > 3 else 8
    jobs = []  # (contest, the limit relaxed or None, the limits run)
    for contest in random_contests(seed, count):
        jobs.append((contest, None, contest[3]))
        for key in contest[3]:
            looser = dict(contest[3])
            looser[key] *= 1.1
            jobs.append((contest, key, looser))
    with ThreadPoolExecutor(2) as pool:
        results = list(pool.map(lambda job: run(verify, *job[0][:3], job[2]), jobs))
    non_monotone = untrue = total = 0
    base = {}
    for (contest, key, _), result in zip(jobs, results):
        if key is None:
            base = result
            print(*contest, "->", round(result["R"], 4) if "R" in result else result.get("error"))
            continue
        if "R" not in base or "R" not in result:
            continue
        total += 1
        gained = result["R"] - base["R"]
        claimed = base["limits"][key.replace("-", "_")].get("gain_if_relaxed_10_percent")
        monotone = gained >= -1e-4 * base["R"]
        true = claimed is not None and abs(claimed - gained) <= 1e-3 * base["R"]
        non_monotone += not monotone
        untrue += not true
        print(f"   {key}: gained {gained:.4f}, claimed {claimed}" + ("" if monotone else " NON-MONOTONE") + ("" if true else " UNTRUE"))
    print(f"relaxations {total}: non-monotone {non_monotone}, untrue gains {untrue}")


if __name__ == "__main__":
    main()
