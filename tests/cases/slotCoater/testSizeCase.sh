# Sourced by the tests that run the slot-coater tutorial (needs: here, the
# folder of this file, and work): a fresh copy of the tutorial in work at
# test size, and cd there.
#
# Test size: the tutorial's geometry shrunk 5 times (gap 10 um, slot 20 um,
# 1.25 um cells; about 2000 particles), a write every 0.2 us.
tutorial="$here/../../../tutorials/slotCoater"
rm -rf "$work"
mkdir -p "$work"
cp -r "$tutorial"/* "$work"
cd "$work"
# Start from the committed files, whatever a run in the source tree left
./Allclean > /dev/null

set_param()
{
    foamDictionary -entry "$1" -set "$2" system/slotCoaterParameters > /dev/null
}
set_param gap 10e-6;          set_param nGap 8
set_param slotWidth 20e-6;    set_param nSlotWidth 16
set_param slotLength 5e-6;    set_param nSlotLength 4
set_param upstreamLip 5e-6;   set_param nUpstreamLip 4
set_param downstreamLip 10e-6; set_param nDownstreamLip 8
set_param wetThickness 4e-6
# (sed, not foamDictionary -set, which drops the #includeIfPresent)
sed -i "s/^writeInterval .*/writeInterval   20;/" system/controlDict
