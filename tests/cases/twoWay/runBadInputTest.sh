#!/bin/bash
# Bad two-way settings must stop colloidDEMFoam before anything is written,
# with a non-zero exit and a message naming the file, the keyword and what
# is allowed.
#
# usage: runBadInputTest.sh variant packDir workDir
#   variants: unknownForceModel unknownDragModel epsilonMinZero
#             epsilonMinOne unknownModelType subCycles steadyState noPIMPLE
#             modelBPressureGradient modelAWithoutPressureGradient
#             epsilonMinAboveBed (the bed's cells, eps ~ 0.39, below
#             epsilonMin 0.5: the fluid fraction would be clipped)
#             unknownKernel kernelRadiusWithCellPoint
#             freeFluidFractionZero backwardScheme
set -e
variant=$1
pack=$2
work=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/prepareCase.sh"
cp -r 0.orig 0
blockMesh > log.blockMesh 2>&1

props=constant/couplingProperties
case $variant in
    unknownForceModel)
        foamDictionary $props -entry forceModels -set "(gravityBuoyancy lift)" > /dev/null
        expect="Unknown force model 'lift' \(keyword 'forceModels' in .*couplingProperties\"?\)" ;;
    unknownDragModel)
        foamDictionary $props -entry dragModel -set ergun > /dev/null
        expect="Unknown dragModel 'ergun' \(keyword 'dragModel' in .*couplingProperties\"?\)" ;;
    epsilonMinZero)
        foamDictionary $props -entry twoWay/epsilonMin -set 0 > /dev/null
        expect="Keyword 'epsilonMin' in .*couplingProperties.twoWay\"? is 0; allowed range: \(0, 1\)" ;;
    epsilonMinOne)
        foamDictionary $props -entry twoWay/epsilonMin -set 1 > /dev/null
        expect="Keyword 'epsilonMin' in .*couplingProperties.twoWay\"? is 1; allowed range: \(0, 1\)" ;;
    unknownModelType)
        foamDictionary $props -entry twoWay/modelType -set C > /dev/null
        expect="Keyword 'modelType' in .*couplingProperties.twoWay\"? is 'C'; allowed: A .* or B" ;;
    subCycles)
        # 10 DEM steps of 1e-6 s do not make a fluid step of 1.5e-5 s
        foamDictionary system/controlDict -entry deltaT -set 1.5e-05 > /dev/null
        expect="Keyword 'deltaT' in .*controlDict\"? is 1.5e-05 s but must equal DEM couplingInterval x timeStep = 10 x 1e-06" ;;
    steadyState)
        foamDictionary system/fvSchemes -entry ddtSchemes/default -set steadyState > /dev/null
        expect="couplingMode twoWay solves the fluid in time with the exchange's stability limit derived for Euler: keyword 'default' of ddtSchemes in .*fvSchemes.ddtSchemes\"? is 'steadyState'; allowed: Euler" ;;
    backwardScheme)
        foamDictionary system/fvSchemes -entry ddtSchemes/default -set backward > /dev/null
        expect="couplingMode twoWay solves the fluid in time with the exchange's stability limit derived for Euler: keyword 'default' of ddtSchemes in .*fvSchemes.ddtSchemes\"? is 'backward'; allowed: Euler" ;;
    noPIMPLE)
        foamDictionary system/fvSolution -entry PIMPLE -remove > /dev/null
        expect="couplingMode twoWay needs a 'PIMPLE' dictionary in .*fvSolution" ;;
    modelAWithoutPressureGradient)
        foamDictionary $props -entry forceModels -set "(gravityBuoyancy)" > /dev/null
        expect="Keyword 'forceModels' in .*couplingProperties\"? lacks 'pressureGradient', which modelType A needs" ;;
    modelBPressureGradient)
        foamDictionary $props -entry twoWay/modelType -set B > /dev/null
        expect="Force model 'pressureGradient' \(keyword 'forceModels' in .*couplingProperties\"?\) with modelType B" ;;
    epsilonMinAboveBed)
        foamDictionary $props -entry twoWay/epsilonMin -set 0.5 > /dev/null
        expect="the particles leave less fluid than twoWay/epsilonMin 0.5 in [0-9]+ cells \(lowest 0\.[0-9]+\) of constant/couplingProperties" ;;
    unknownKernel)
        foamDictionary $props -entry twoWay/kernel -set gaussian > /dev/null
        expect="Keyword 'kernel' in .*couplingProperties\"?::twoWay is 'gaussian'; allowed: .*cellPoint.*satellite" ;;
    kernelRadiusWithCellPoint)
        foamDictionary $props -entry twoWay/kernel -set cellPoint > /dev/null
        foamDictionary $props -entry twoWay/kernelRadius -set 1e-4 > /dev/null
        expect="Keyword 'kernelRadius' in .*couplingProperties.twoWay\"? is 0.0001 m, but 'kernel' is 'cellPoint', whose support is set by the mesh; allowed: 0" ;;
    freeFluidFractionZero)
        foamDictionary $props -entry twoWay/freeFluidFraction -add 0 > /dev/null
        expect="Keyword 'freeFluidFraction' in .*couplingProperties.twoWay\"? is 0; allowed range: \(0, 1\] \(default 0.445, random loose packing\)" ;;
    *)  echo "unknown variant $variant"; exit 2 ;;
esac

source "$here/../common/expectBadInput.sh"
