# Sourced by the agglomeration tests that run colloidDEMFoam in the
# coupling tests' channel (tests/cases/coupling/case: 100 x 100 x 50 um,
# spheres of d = 1 um).  Needs: here (this folder), work.
#
#   newChannelCase             a fresh copy in work, cd there
#   runLength END INTERVAL     endTime END [s], a write every INTERVAL steps
#   includeParticles FILE      the DEM script creates the particles of FILE
#                              (create_atoms lines) instead of its own
#   resumableBox               the DEM script reads the DEM state of a
#                              resumed run (colloid_restart 1) instead of
#                              creating the box
#   meshAndQuiescentFluid      mesh, U = 0
#   runChannelSolver MODE [resume]
#                              serial | parallel (2 ranks; reconstructed);
#                              resume: a parallel run already decomposed

newChannelCase()
{
    rm -rf "$work"
    mkdir -p "$(dirname "$work")"
    cp -r "$here/../coupling/case" "$work"
    cd "$work"
}

runLength()
{
    sed -i -e "s/^endTime .*/endTime $1;/" -e "s/^writeInterval .*/writeInterval $2;/" \
        system/controlDict
}

includeParticles()
{
    sed -i -e '/^create_atoms/d' \
        -e "s|^set .*group all|include         $1\n&|" constant/DEM/in.liggghts
    grep -q "^include *$1" constant/DEM/in.liggghts
}

resumableBox()
{
    awk '/^(atom_style|boundary|region +domain|create_box) /{
             $1 = $1; held = held sprintf("    \"%s\" &\n", $0)
             if ($1 != "create_box") next
             printf "if \"${colloid_restart} == 0\" then &\n%selse &\n", held
             print "    \"read_restart ${colloid_restart_file}\""; next }
         { print }' constant/DEM/in.liggghts > constant/DEM/in.liggghts.new
    mv constant/DEM/in.liggghts.new constant/DEM/in.liggghts
    grep -q 'read_restart ${colloid_restart_file}' constant/DEM/in.liggghts \
        || { echo "FAIL: resumableBox: no create_box in constant/DEM/in.liggghts"; exit 1; }
}

meshAndQuiescentFluid()
{
    blockMesh > log.blockMesh 2>&1
    mkdir -p 0
    postProcess -func writeCellCentres -time 0 > log.writeCellCentres 2>&1
    python3 "$here/../coupling/setPoiseuilleU.py" . 1e-4 0
}

runChannelSolver()
{
    case $1 in
        serial) colloidDEMFoam > log.colloidDEMFoam 2>&1 || { tail -30 log.colloidDEMFoam; exit 1; } ;;
        parallel)
            [ "${2:-}" = resume ] || decomposePar > log.decomposePar 2>&1
            mpirun -np 2 colloidDEMFoam -parallel > log.colloidDEMFoam 2>&1 \
                || { tail -30 log.colloidDEMFoam; exit 1; }
            reconstructPar -newTimes > log.reconstructPar 2>&1 ;;
        *) echo "usage: $0 serial|parallel workDir" 1>&2; exit 1 ;;
    esac
}
