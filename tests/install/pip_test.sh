#!/usr/bin/env bash
# The Python package installed as a user installs it (issue 62, pyproject.toml): a venv of
# Debian's interpreter with its system site packages (numpy), `pip install
# --no-build-isolation` from the checkout, offline, with setup.py's CMake build pointed at
# this build folder (MMVLAB_CMAKE_BUILD_DIR) so that it compiles nothing new; then, from
# outside the checkout, the installed package runs a study (its plugins found beside the
# module, not in the build folder), says its version, pickles a scene across a process
# pool, and its stubs and docstrings cover every study.
#
#   tests/install/pip_test.sh BUILD_DIR PYTHON
set -euo pipefail
build=$(cd "${1:?usage: pip_test.sh BUILD_DIR PYTHON}" && pwd)
python=${2:?usage: pip_test.sh BUILD_DIR PYTHON}
root=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d /tmp/mmvlab_pip_XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "pip_test: $*" >&2; exit 1; }

"$python" -m venv --system-site-packages --without-pip "$tmp/venv" || fail "$python -m venv failed"
venv_python=$tmp/venv/bin/python
# A copy of the checkout (as a user's clone: setuptools writes its work folders there),
# without the build folders.
mkdir "$tmp/src"
(cd "$root" && git ls-files -z --cached --others --exclude-standard | xargs -0 cp --parents -t "$tmp/src") ||
  fail "could not copy the checkout (git ls-files)"
MMVLAB_CMAKE_BUILD_DIR=$build PIP_NO_INDEX=1 "$venv_python" -m pip install --no-build-isolation --no-deps -q "$tmp/src" \
  > "$tmp/pip.log" 2>&1 || { tail -40 "$tmp/pip.log" >&2; fail "pip install failed"; }
version=$(sed -n 's/^project(mmvlab VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
cd "$tmp"
rm -rf "$tmp/src"  # nothing is imported from the checkout
LD_DEBUG=files LD_DEBUG_OUTPUT=$tmp/ld "$venv_python" - "$version" "$root" <<'PY' || fail "the installed package failed"
import os, pickle, sys, concurrent.futures, inspect
import mmvlab
assert mmvlab.__version__ == sys.argv[1], (mmvlab.__version__, sys.argv[1])
site = os.path.dirname(mmvlab.__file__)
assert site.startswith(sys.prefix), (site, sys.prefix)
for name in ("py.typed", "__init__.pyi", "libmmvlab_sundials.so", "libmmvlab_mat.so"):
    assert os.path.exists(os.path.join(site, name)), name
scene = mmvlab.load_scene(set={"links.link1.length": 2.0})
m = mmvlab.modes(scene, segments=4, modes=3)
assert m.frequencies_hz.shape == (3,) and m.frequencies_hz[0] > 0
# A scene and a result pickle; a process pool runs studies on pickled scenes.
again = pickle.loads(pickle.dumps(scene))
assert (again.name, again.source, again.kind) == (scene.name, scene.source, scene.kind)
r2 = pickle.loads(pickle.dumps(m))
assert (r2.frequencies_hz == m.frequencies_hz).all() and r2.json == m.json
with concurrent.futures.ProcessPoolExecutor(2) as pool:
    pooled = list(pool.map(mmvlab.modes, [scene, again]))
direct = mmvlab.modes(scene)
for x in pooled:
    assert abs(x.frequencies_hz - direct.frequencies_hz).max() <= 1e-12 * direct.frequencies_hz.max()
# SUNDIALS through the plugin beside the module.
run = mmvlab.simulate(mmvlab.load_scene(os.path.join(sys.argv[2], "scenes", "mmv-slew.yaml")), segments=2,
                      integrator="cvode_bdf", duration=0.02)
assert run.json["integrator"] == "cvode_bdf", run.json.get("integrator")
# Every study has a docstring naming each of its parameters.
for name in mmvlab.__all__:
    obj = getattr(mmvlab, name)
    if inspect.isfunction(obj):
        doc = inspect.getdoc(obj) or ""
        for p in inspect.signature(obj).parameters:
            assert p in doc, f"mmvlab.{name}'s docstring does not say what `{p}` is"
print("ok")
PY
ld=$(cat "$tmp"/ld.*)
grep -q "file=$tmp/venv/lib/python3[^ ]*/site-packages/mmvlab/libmmvlab_sundials.so .*dynamically loaded" <<<"$ld" ||
  fail "the SUNDIALS plugin was not loaded from the installed package"
! grep -q "file=$build/libmmvlab_" <<<"$ld" || fail "a plugin was loaded from the build folder"
echo "pip_test: pip-installed into a venv; a study, CVODE through the package's plugin, pickling, version and docstrings"
