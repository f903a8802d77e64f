# Sourced by the two-way test scripts: the environment, and a copy of the
# packedBed case in $work with the packed bed of $pack (makePack.sh).
# Needs: here (this folder), pack, work.
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
set +u
source "$here/../../../etc/bashrc"
set -u

rm -rf "$work"
mkdir -p "$(dirname "$work")"
cp -r "$here/packedBed" "$work"
cd "$work"
cp "$pack/bed.data" constant/DEM/
