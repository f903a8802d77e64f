# Sourced by the script tests that run the stock liggghts with the plugin
# preloaded (run*ParallelTest.sh): $liggghts and $plugin set by the script.
#
#   runLiggghts ranks input tag [-var name value ...]
# runs input on 1 rank or on 2 (mpirun), writing log.<tag>.<ranks> and
# screen.<tag>.<ranks>, with -var ranks <ranks> and the variables given;
# on failure prints FAIL with the screen's end and exits.
runLiggghts()
{
    local ranks=$1 input=$2 tag=$3
    shift 3
    local args=(-in "$input" -var ranks "$ranks" "$@" -log "log.$tag.$ranks")
    if [ "$ranks" = 1 ]
    then
        LD_PRELOAD="$plugin" "$liggghts" "${args[@]}" > "screen.$tag.$ranks" 2>&1
    else
        LD_PRELOAD="$plugin" mpirun -np 2 -x LD_PRELOAD "$liggghts" "${args[@]}" > "screen.$tag.$ranks" 2>&1
    fi || { echo "FAIL: the run $tag on $ranks rank(s)"; tail -20 "screen.$tag.$ranks"; exit 1; }
}
