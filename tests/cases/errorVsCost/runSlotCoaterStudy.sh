#!/bin/bash
# colloidErrorStudy on the slot-coater tutorial at test size (about 2000
# particles, testSizeCase.sh), run to END_TIME, with the tutorial's own
# system/errorStudyDict restricted to SETTINGS (comma-separated); then
# checkSlotCoaterStudy.py.
#
# usage: runSlotCoaterStudy.sh workDir endTime settings
set -e
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
work=$1
endTime=$2
settings=$3
here=$(cd "$(dirname "$0")" && pwd)
set +u
source "$here/../../../etc/bashrc" || exit 1
set -u

studyDir=$here
here="$studyDir/../slotCoater"     # testSizeCase.sh finds the tutorial from it
source "$here/testSizeCase.sh"
here=$studyDir
sed -i "s|^run .*|run         \"./Allrun -endTime $endTime\";|" system/errorStudyDict

colloidErrorStudy -settings "$settings"
cat errorStudy/errorStudy.md
/usr/bin/python3 "$here/checkSlotCoaterStudy.py" errorStudy
