#!/usr/bin/env bash
# The README's two commands are the product's front door: CI must run the second one
# verbatim (then the sanitizer suite), the first must install only what building and
# running needs, and setup.sh must refuse an option it does not know.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
fail() { echo "front_door: $*" >&2; exit 1; }

mapfile -t cmds < <(awk '/^```sh$/{f=1;next} /^```$/{f=0} f' "$root/README.md" | grep -E '^\./setup\.sh')
((${#cmds[@]} >= 2)) || fail "README.md: expected the two commands in \`\`\`sh blocks, found ${#cmds[@]}"
run="${cmds[0]}"; test="${cmds[1]}"
[[ "$run" == "./setup.sh && "* ]] || fail "README command 1 must start with './setup.sh && ' (no --test): $run"
[[ "$run" == *"--target mmvlab"* ]] || fail "README command 1 must build only the executable: $run"
[[ "$test" == "./setup.sh --test && "* ]] || fail "README command 2 must start with './setup.sh --test && ': $test"
[[ "$test" != *sanitized* ]] || fail "README command 2 must run the plain suite only: $test"
grep -qxF "$test && tests/second_arithmetic.sh build && tests/sanitized.sh" "$root/.ci/run" ||
  fail ".ci/run does not run README command 2 verbatim followed by tests/second_arithmetic.sh build and tests/sanitized.sh"

# setup.sh without --test names no test-only package; with --test it adds them.
plain=$(sed -n '/^build_pkgs=(/,/^)/p' "$root/setup.sh")
for p in libgtest-dev libbenchmark-dev octave python3-pytest python3-vtk9 chromium python3-pip python3-venv; do
  ! grep -qw -- "$p" <<<"$plain" || fail "setup.sh installs $p without --test"
  sed -n '/^test_pkgs=(/,/^)/p' "$root/setup.sh" | grep -qw -- "$p" || fail "setup.sh --test does not install $p"
done
# The Python module is part of the product (built by the full build, imported by users).
for p in pybind11-dev python3-dev python3-numpy; do
  grep -qw -- "$p" <<<"$plain" || fail "setup.sh does not install $p, which the Python module needs to build and import"
done
set +e; bash "$root/setup.sh" --bogus 2>/tmp/front_door.$$; rc=$?; set -e
msg=$(cat /tmp/front_door.$$); rm -f /tmp/front_door.$$
((rc == 64)) || fail "setup.sh --bogus exited $rc, expected 64"
grep -q "unknown option '--bogus'" <<<"$msg" || fail "setup.sh --bogus said: $msg"
echo "front_door: README commands, .ci/run and setup.sh agree"
