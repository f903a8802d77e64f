# Sourced by the filtration input tests (run*InputTest.sh) with their work
# folder: copies the case there (and changes to it), and gives them the
# check of a value that system/filtrationParameters must refuse.
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/../twoWay/caseFunctions.sh"
copyCase "$COLLOIDFOAM_TUTORIALS/filtration" "$1"
params=system/filtrationParameters
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# refused key value allowed: with "key value;" prepareRun.sh exits
# non-zero, its message names the file, the key, the value and the allowed
# values (allowed, as the message words them), and it writes no DEM files
refused() {
    local key=$1 bad=$2 allowed=$3 message part
    rm -rf DEM
    sed -i "s/^$key .*/$key $bad;/" $params
    if "$COLLOIDFOAM_TUTORIALS/filtration/prepareRun.sh" > log.prepareRun 2> log.error
    then
        fail "$key $bad: prepareRun.sh exited 0"
    fi
    message=$(cat log.error)
    for part in "$params" "'$key'" "is $bad;" "$allowed"
    do
        [[ "$message" == *"$part"* ]] \
            || fail "$key $bad: the message '$message' lacks '$part'"
    done
    [ ! -e DEM/filtration.liggghts ] && [ ! -e DEM/suspension.data ] \
        || fail "$key $bad: DEM files written"
    echo "$key $bad: $message"
}
