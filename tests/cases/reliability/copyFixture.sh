# Sourced by the reliability tests (needs: here, fixture, work): the
# environment (testEnvironment.sh), then a fresh copy of the fixture run in
# work, and cd there (the tests write into their copy, never into the
# fixture).
source "$here/testEnvironment.sh"

[ -d "$fixture" ] || { echo "no fixture run $fixture" 1>&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"
cp -r "$fixture"/. "$work"
cd "$work"
