# Sourced by the two-way test scripts (needs: here, this folder): the
# environment and the steps every script shares.
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the source tree
set +u
source "$here/../../../etc/bashrc"
set -u

# copyCase source work: a fresh copy of a case in work (a tutorial that
# was run holds its results: cleaned), and cd there
copyCase() {
    rm -rf "$2"
    mkdir -p "$(dirname "$2")"
    cp -r "$1" "$2"
    cd "$2"
    if [ -x Allclean ]
    then
        ./Allclean > /dev/null
    fi
}

# setModel A|B: modelType; Model B's drag (K/eps) carries the pressure
# gradient, so its force list has no pressureGradient
setModel() {
    foamDictionary constant/couplingProperties -entry twoWay/modelType \
        -set "$1" > /dev/null
    if [ "$1" = B ]
    then
        foamDictionary constant/couplingProperties -entry forceModels \
            -set "(gravityBuoyancy)" > /dev/null
    fi
}

# runSolver nProcs: colloidDEMFoam serial, or decomposed (METIS) on nProcs
# ranks and reconstructed
runSolver() {
    if [ "$1" -gt 1 ]
    then
        decomposePar > log.decomposePar 2>&1
        mpirun -np "$1" colloidDEMFoam -parallel > log.colloidDEMFoam 2>&1 \
            || { tail -30 log.colloidDEMFoam; exit 1; }
        reconstructPar > log.reconstructPar 2>&1
    else
        colloidDEMFoam > log.colloidDEMFoam 2>&1 \
            || { tail -30 log.colloidDEMFoam; exit 1; }
    fi
}

# setKernel [kernel [radius]]: the deposit kernel of the case's
# couplingProperties (twoWay/kernel; the satellite kernel's kernelRadius
# set to radius [m] if given, removed for another kernel); no argument:
# the case's own.  The test scripts pass $COLLOIDFOAM_KERNEL and
# $COLLOIDFOAM_KERNEL_RADIUS, set by
# ctest for the kernel variants of a test.
setKernel() {
    if [ -n "${1:-}" ]
    then
        foamDictionary constant/couplingProperties -entry twoWay/kernel \
            -set "$1" > /dev/null
        if [ -n "${2:-}" ]
        then
            foamDictionary constant/couplingProperties \
                -entry twoWay/kernelRadius -set "$2" > /dev/null
        fi
        if [ "$1" != satellite ] && foamDictionary constant/couplingProperties \
            -entry twoWay/kernelRadius > /dev/null 2>&1
        then
            foamDictionary constant/couplingProperties \
                -entry twoWay/kernelRadius -remove > /dev/null
        fi
    fi
}

# checkTranspose: the deposit kernel checks at every sample that it is
# the transpose of the deposit (debug switch; checkFluidFraction.py reads
# the log lines)
checkTranspose() {
    cat >> system/controlDict <<'DICT'

DebugSwitches
{
    depositKernel   1;
}
DICT
}
