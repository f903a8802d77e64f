# Sourced by the reliability tests (needs: here, fixture, work): the
# environment, then a fresh copy of the fixture run in work, and cd there
# (the tests write into their copy, never into the fixture).
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
set +u
source "$here/../../../etc/bashrc" || exit 1
set -u

[ -d "$fixture" ] || { echo "no fixture run $fixture" 1>&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"
cp -r "$fixture"/. "$work"
cd "$work"
