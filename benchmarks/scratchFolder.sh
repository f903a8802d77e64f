# Sourced by the benchmarks: their scratch folders (-dir), which they empty
# only if they made them.
#
#   scratchFolderCheck DIR NAME   stop unless DIR is new or was made by NAME
#   scratchFolderFresh DIR NAME   the check, then DIR emptied and marked
#                                 as NAME's (the file DIR/.NAME)
scratchFolderCheck()
{
    if [ -e "$1" ] && [ ! -f "$1/.$2" ]
    then
        echo "$2: $1 exists and was not made by this script; choose another -dir" 1>&2
        exit 1
    fi
}

scratchFolderFresh()
{
    scratchFolderCheck "$1" "$2"
    rm -rf "$1"
    mkdir -p "$1"
    touch "$1/.$2"
}
