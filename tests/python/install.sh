#!/usr/bin/env bash
# install.sh PYTHON SOURCE BUILD WORK: the package installs as a user installs it (docs/python.md): into a
# fresh venv that sees Debian's NumPy, by pip with no build isolation and no index (nothing is
# downloaded), its module taken from BUILD (TREBUCHET_BUILD_DIR) rather than compiled again. The
# installed package then gives its version and shoots, away from the source tree.
set -euo pipefail
python=$1 source_dir=$2 build_dir=$3 work=$4
rm -rf "$work"
"$python" -m venv --system-site-packages "$work/venv"
TREBUCHET_BUILD_DIR="$build_dir" "$work/venv/bin/pip" install --quiet --no-build-isolation --no-index "$source_dir"
cd "$work"
"$work/venv/bin/python" - <<'PY'
import trebuchet
assert trebuchet.__file__.startswith(__import__("sys").prefix), trebuchet.__file__
print("installed trebuchet", trebuchet.__version__, "commit", trebuchet.__commit__, "at", trebuchet.__file__)
answer = trebuchet.shot(dict(L1="4.13m", L2="0.88m", L3="0.5m", L4="3.55m", M="3t", m="50kg", mb="174kg"))
assert trebuchet.__version__ == "0.1.0" and answer["R"] > 0, answer
print("its shot: R =", answer["R"], "m")
PY
rm -rf "$source_dir/build-python" "$source_dir"/python/*.egg-info
