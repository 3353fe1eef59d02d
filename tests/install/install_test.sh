#!/usr/bin/env bash
# `cmake --install` as a user runs it (issue 62): the build installed to a temporary
# prefix; from there, with the build folder out of sight (the installed binary is run
# from the prefix, and the dynamic loader's log must show every plugin loaded from
# PREFIX/lib/mmvlab, never from the build), `modes` on the embedded scene and on an
# installed scene, `render` (the figures plugin, OSMesa), a CVODE run (the SUNDIALS
# plugin) and `--version`, which must be CMakeLists.txt's project version.
#
#   tests/install/install_test.sh BUILD_DIR
set -euo pipefail
build=$(cd "${1:?usage: install_test.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d /tmp/mmvlab_install_XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "install_test: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log" || { cat "$tmp/install.log" >&2; fail "cmake --install failed"; }
bin=$tmp/prefix/bin/mmvlab
[[ -x $bin ]] || fail "no executable at $bin"
for p in figures sundials mat video; do
  [[ -f $tmp/prefix/lib/mmvlab/libmmvlab_$p.so ]] || fail "plugin libmmvlab_$p.so not installed in PREFIX/lib/mmvlab"
done
for f in share/mmvlab/scenes/mmv.yaml share/mmvlab/scenes/hamsas.yaml share/mmvlab/sweeps/link3-sizing.yaml \
         share/doc/mmvlab/README.md share/doc/mmvlab/cluster/sweep.slurm share/doc/mmvlab/cluster/sweep.sub; do
  [[ -f $tmp/prefix/$f ]] || fail "$f not installed"
done

version=$(sed -n 's/^project(mmvlab VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
[[ $("$bin" --version) == "mmvlab $version" ]] || fail "--version says '$("$bin" --version)', not 'mmvlab $version'"

# loaded PLUGIN LOGFILE: the loader's log shows PLUGIN opened from the prefix only.
loaded() {
  grep -q "file=$tmp/prefix/lib/mmvlab/libmmvlab_$1.so .*dynamically loaded" "$2" ||
    fail "libmmvlab_$1.so was not loaded from PREFIX/lib/mmvlab (log: $2)"
  ! grep -q "file=$build/libmmvlab_" "$2" || fail "a plugin was loaded from the build folder"
}
cd "$tmp"
"$bin" modes > modes.txt || fail "installed modes failed"
grep -q "^System modes about the equilibrium" modes.txt || fail "installed modes printed no mode table"
"$bin" modes "$tmp/prefix/share/mmvlab/scenes/mmv-slew.yaml" --segments 4 > slew.txt || fail "modes on an installed scene failed"
LD_DEBUG=files LD_DEBUG_OUTPUT=$tmp/render.ld "$bin" render --out article.png --size 320x240 2> render.err ||
  { cat render.err >&2; fail "installed render failed"; }
[[ $(head -c 8 article.png | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] || fail "render wrote no PNG"
loaded figures "$(ls "$tmp"/render.ld.*)"
LD_DEBUG=files LD_DEBUG_OUTPUT=$tmp/cvode.ld "$bin" simulate "$tmp/prefix/share/mmvlab/scenes/mmv-slew.yaml" --segments 2 \
  --duration 0.05 --integrator cvode_bdf > cvode.txt 2> cvode.err || { cat cvode.err >&2; fail "installed CVODE run failed"; }
loaded sundials "$(ls "$tmp"/cvode.ld.*)"
echo "install_test: installed to a prefix; modes, render (figures plugin) and CVODE (SUNDIALS plugin) ran from it"
