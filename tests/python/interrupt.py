"""interrupt.py: a Monte Carlo run of the largest size the library allows (500 000 shots), stopped
by SIGINT half a second in, as Ctrl-C stops it. Prints how long the stop took, from the signal to
the run's return with its threads joined (docs/benchmarks.md: goal 0.2 s), and exits 0 when the
run raised KeyboardInterrupt and the process has as many threads as before it (/proc/self/task:
Python's threading does not see a library's own threads)."""
import os
import signal
import sys
import threading
import time

import trebuchet


def threads():
    return len(os.listdir("/proc/self/task"))


before = threads()
design = dict(L1="4.13m", L2="0.88m", L3="0.5m", L4="3.55m", M="2.9t..3.3t", m="50kg", mb="174kg")
sent = []
timer = threading.Timer(0.5, lambda: (sent.append(time.monotonic()), os.kill(os.getpid(), signal.SIGINT)))
timer.start()
try:
    trebuchet.monte_carlo(design, samples=500000, threads=2)
    print("the run finished: SIGINT did not stop it")
    sys.exit(1)
except KeyboardInterrupt:
    stopped = time.monotonic()
timer.join()
# A joined thread's task leaves /proc/self/task as the kernel ends it, a moment after the join.
deadline = time.monotonic() + 2
while threads() != before and time.monotonic() < deadline:
    time.sleep(0.01)
after = threads()
print(f"KeyboardInterrupt {stopped - sent[0]:.3f} s after SIGINT; threads before the run {before}, after {after}")
sys.exit(0 if after == before else 2)
