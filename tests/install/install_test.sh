#!/usr/bin/env bash
# A new user's installation: a fresh virtual environment that sees Debian's packages (numpy,
# matplotlib), `pip install .` without network or build isolation, then the package from
# outside the source tree — its version, an environment, a rendered picture — and the `tendril`
# command on PATH, without LibTorch until a model command loads the installed dynamics plugin,
# and a learned-model environment from Python on the model that command fitted;
# and a wheel from `pip wheel .` holding the extension, the program and its plugin.
#   install_test.sh <source dir> <work dir> <python> <CMake build dir for pip>
set -euo pipefail
source=$1 work=$2 python=$3
mkdir -p "$work"
rm -rf "$work/venv" "$work/wheels" "$work/fit"
export TENDRIL_CMAKE_BUILD_DIR=$4
export PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1

start=$(date +%s%N)
"$python" -m venv --system-site-packages "$work/venv"
"$work/venv/bin/pip" install --quiet --no-build-isolation "$source"
installed=$(date +%s%N)
echo "pip install: $(( (installed - start) / 1000000 )) ms"

expected=$(head -n 1 "$source/VERSION")
cd "$work"  # away from the source tree: the installed package, not python/
PATH="$work/venv/bin:$PATH"
[[ $(command -v tendril) == "$work/venv/bin/tendril" ]] || { echo "tendril is not on PATH"; exit 1; }
python - "$expected" "$work/venv" <<'PY'
import importlib.metadata
import os
import sys

import tendril

expected, venv = sys.argv[1], sys.argv[2]
assert tendril.__file__.startswith(venv), f"imported {tendril.__file__}, not the installed package"
assert tendril.__version__ == expected, (tendril.__version__, expected)
assert importlib.metadata.version("tendril") == expected
env = tendril.make("Elastica/Tracking3D-v0", render_mode="rgb_array", render_size=(64, 48))
observation, _ = env.reset(seed=0)
observation, reward, terminated, truncated, info = env.step(env.action_space.sample())
picture = env.render()
assert picture.shape == (48, 64, 3) and picture.std() > 0, picture.shape
print(f"tendril {tendril.__version__} from {os.path.dirname(tendril.__file__)}: "
      f"{len(tendril.registry())} environments, observation {observation.shape}")
PY
tendril --help | head -n 3
tendril list envs | grep -q "Elastica/Tracking3D-v0"
tendril --version | grep -q "tendril $expected"
tendril export --help | grep -q "C header"
tendril plot --help | grep -q "curves"
# LibTorch only with the installed dynamics plugin, loaded by a model command: a one-epoch fit.
program=$(python -c "import os, tendril; print(os.path.join(os.path.dirname(tendril.__file__), 'bin', 'tendril'))")
if ldd "$program" | grep -q libtorch; then echo "the installed program links LibTorch"; exit 1; fi
tendril model fit "$source/configs/dynamics/sma_stiff_seq2seq.yaml" -o "$work/fit" --quiet \
  --set data.file="$source/data/sma_limb/stiff_exploration_prepared.csv" --set training.epochs=1 \
  --set training.windows_per_epoch=256 --set evaluation.horizons_s=[1] >"$work/fit.log"
[ -s "$work/fit/model.tdm" ] || { echo "the installed program fitted no model"; exit 1; }
# The same model drives a learned-model environment from the installed Python package.
python - "$work/fit" <<'PY'
import sys

import numpy as np
import tendril

env = tendril.make("SmaLimb/LearnedReach-v0", model=sys.argv[1])
observation, _ = env.reset(seed=0)
observation, reward, terminated, truncated, info = env.step(env.action_space.sample())
assert np.all(np.isfinite(observation)) and np.isfinite(reward), (observation, reward)
print(f"SmaLimb/LearnedReach-v0 from Python on {sys.argv[1]}: observation {observation.shape}")
PY
rm -rf "$work/fit"

"$work/venv/bin/pip" wheel --quiet --no-build-isolation --no-deps -w "$work/wheels" "$source"
echo "pip wheel: $(( ($(date +%s%N) - installed) / 1000000 )) ms"
python - "$work/wheels" "$expected" <<'PY'
import glob
import sys
import zipfile

wheels = glob.glob(f"{sys.argv[1]}/tendril-{sys.argv[2]}-*.whl")
assert len(wheels) == 1, wheels
names = zipfile.ZipFile(wheels[0]).namelist()
for needed in ("tendril/bin/tendril", "tendril/bin/libtendril_dynamics_plugin.so",
               "tendril/_version.py", "tendril_plot/__main__.py"):
    assert needed in names, f"{needed} missing from {wheels[0]}"
assert any(n.startswith("tendril/_tendril") and n.endswith(".so") for n in names), names
mode = zipfile.ZipFile(wheels[0]).getinfo("tendril/bin/tendril").external_attr >> 16
assert mode & 0o111, "the program is not executable in the wheel"
print(f"wheel {wheels[0].rsplit('/', 1)[1]}: {len(names)} files")
PY
echo "install test passed"
