# Sourced by the packed-bed test scripts (needs: here, pack, work): a copy
# of the packedBed tutorial case in $work with the packed bed of $pack
# (makePack.sh).
source "$here/caseFunctions.sh"
copyCase "$COLLOIDFOAM_TUTORIALS/twoWay/packedBed" "$work"
cp "$pack/bed.data" constant/DEM/
