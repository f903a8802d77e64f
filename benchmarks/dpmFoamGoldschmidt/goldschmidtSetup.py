"""colloidDEMFoam's twin of OpenFOAM's DPMFoam Goldschmidt tutorial: every
physical value is read from the tutorial's own files (OpenFOAM's
foamDictionary), so the two runs cannot disagree on one.

    python3 goldschmidtSetup.py TUTORIAL CASE ENDTIME WRITEINTERVAL SUBSTEPS

TUTORIAL  the DPMFoam tutorial (OpenFOAM's source package)
CASE      a copy of benchmarks/dpmFoamGoldschmidt/case, filled in here
SUBSTEPS  DEM steps per DPMFoam time step: DPMFoam's largest number of
          collision sub-cycles in its run, so that the DEM step is never
          longer than DPMFoam's collision step

Writes CASE/constant/DEM/goldschmidt.data (the particles, um),
CASE/constant/DEM/goldschmidt.liggghts (materials and wall positions) and
fills the @name@ values of the case's dictionaries.

Contact: DPMFoam's pair and wall spring-slider-dashpot models are Hertz
with the normal damping alpha sqrt(m* k_N) delta^(1/4), k_N = 4/3 E*
sqrt(R*) (Tsuji et al. 1992).  LIGGGHTS' hertz has the same form,
2 sqrt(5/6) |beta| sqrt(2 E* sqrt(R* delta) m*), with beta = ln e /
sqrt(ln^2 e + pi^2): equal when |beta| = alpha / sqrt(5), which gives
the coefficient of restitution set here.  E*, G* and R* are formed the
same way in both; the tangential damping is LIGGGHTS' (sqrt(4 G*/E*) =
0.89 times DPMFoam's for pairs, 0.91 for walls; DPMFoam takes the normal
one), and a sliding contact keeps its spring at the Coulomb limit in
LIGGGHTS where DPMFoam sets it to zero.

Also imported by tests/cases/twoWay/checkDpmContact.py (entry, the
dictionary paths)."""
import math
import os
import re
import subprocess
import sys


# DPMFoam's particle properties and its contact models' coefficients
CLOUD = os.path.join("constant", "kinematicCloudProperties")
PAIR = "subModels/pairCollisionCoeffs/pairSpringSliderDashpotCoeffs/"
WALL = "subModels/pairCollisionCoeffs/wallSpringSliderDashpotCoeffs/"
DIAMETER = "subModels/injectionModels/model1/sizeDistribution/fixedValueDistribution/value"


def entry(path, key):
    """One value of an OpenFOAM dictionary, as foamDictionary reads it"""
    out = subprocess.run(["foamDictionary", "-entry", key, "-value", path],
                         capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit("goldschmidtSetup: %s: cannot read '%s':\n%s" % (path, key, out.stdout + out.stderr))
    return out.stdout.strip()


def numbers(text):
    return [float(v) for v in re.findall(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", text)]


def list_body(path):
    """The text of an OpenFOAM list file after its header, comments removed"""
    text = re.sub(r"/\*.*?\*/", "", open(path).read(), flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    return text[text.index("}", text.index("FoamFile")) + 1:]


def restitution(alpha):
    """LIGGGHTS' coefficient of restitution whose hertz damping equals
    DPMFoam's alpha"""
    beta = alpha/math.sqrt(5.0)
    return math.exp(-beta*math.pi/math.sqrt(1.0 - beta*beta))


def patch_rebound(text, patch):
    """e and mu of one patch of localInteractionCoeffs (a list of
    dictionaries that foamDictionary cannot address)"""
    block = text[text.index("localInteractionCoeffs"):]
    m = re.search(r"\b%s\s*\{([^}]*)\}" % patch, block)
    if not m:
        sys.exit("goldschmidtSetup: no patch '%s' in localInteractionCoeffs" % patch)
    values = dict(re.findall(r"(\w+)\s+([^;\s]+)\s*;", m.group(1)))
    if values.get("type") != "rebound":
        sys.exit("goldschmidtSetup: patch '%s' is not 'rebound'" % patch)
    return float(values["e"]), float(values["mu"])


def main():
    tutorial, case, end_time, write_interval, substeps = sys.argv[1:6]
    substeps = int(substeps)
    cloud = os.path.join(tutorial, CLOUD)
    E = float(entry(cloud, "constantProperties/youngsModulus"))     # [Pa]
    nu_p = float(entry(cloud, "constantProperties/poissonsRatio"))
    rho_p = float(entry(cloud, "constantProperties/rho0"))          # [kg/m^3]
    alpha_max = float(entry(cloud, "constantProperties/alphaMax"))
    d = float(entry(cloud, DIAMETER))
    alpha_pp, mu_pp = float(entry(cloud, PAIR + "alpha")), float(entry(cloud, PAIR + "mu"))
    if float(entry(cloud, PAIR + "b")) != 1.5 or float(entry(cloud, WALL + "b")) != 1.5:
        sys.exit("goldschmidtSetup: DPMFoam's contact is not Hertzian (b != 1.5)")
    alpha_pw, mu_pw = float(entry(cloud, WALL + "alpha")), float(entry(cloud, WALL + "mu"))
    E_w, nu_w = float(entry(cloud, WALL + "youngsModulus")), float(entry(cloud, WALL + "poissonsRatio"))
    e_sym, mu_sym = patch_rebound(open(cloud).read(), "frontAndBack")
    transport = os.path.join(tutorial, "constant", "transportProperties")
    rho_f = float(entry(transport, "rho.air"))
    nu_f = float(entry(transport, "nu"))
    inlet = numbers(entry(os.path.join(tutorial, "0", "U.air"), "boundaryField/bottom/inletVelocity"))
    if inlet[0] != 0 or inlet[1] != 0:
        sys.exit("goldschmidtSetup: the inlet velocity is not vertical")
    control = os.path.join(tutorial, "system", "controlDict")
    delta_t = float(entry(control, "deltaT"))
    block = os.path.join(tutorial, "system", "blockMeshDict")
    scale = float(entry(block, "scale"))
    vertices = numbers(entry(block, "vertices"))
    xs, ys, zs = vertices[0::3], vertices[1::3], vertices[2::3]
    um = 1e6*scale      # blockMesh units -> um
    box = [(min(v)*um, max(v)*um) for v in (xs, ys, zs)]
    if abs(box[0][0] + box[0][1]) > 1e-9 or abs(box[1][0] + box[1][1]) > 1e-9 or box[2][0] != 0:
        sys.exit("goldschmidtSetup: expected a column centred in x and y on z = 0")
    r_um = 0.5e6*d
    # symmetry faces: a wall r - 50 um beyond each, so that a particle
    # touching it has its centre 50 um inside the fluid mesh
    sym_wall = box[0][1] + r_um - 50.0

    positions = numbers(list_body(os.path.join(tutorial, "constant", "kinematicCloudPositions")))
    pts = [positions[k:k + 3] for k in range(0, len(positions) - 2, 3)]
    dem = os.path.join(case, "constant", "DEM")
    with open(os.path.join(dem, "goldschmidt.data"), "w") as f:
        f.write("LIGGGHTS data file: DPMFoam Goldschmidt tutorial, %d spheres (goldschmidtSetup.py)\n\n" % len(pts))
        f.write("%d atoms\n3 atom types\n\n" % len(pts))
        f.write("%g %g xlo xhi\n%g %g ylo yhi\n%g %g zlo zhi\n\nAtoms\n\n"
                % (-sym_wall, sym_wall, box[1][0], box[1][1], box[2][0], box[2][1]))
        for i, p in enumerate(pts):
            f.write("%d 1 %g %g %.6f %.6f %.6f\n" % (i + 1, 2*r_um, rho_p*1e-3, p[0]*1e6, p[1]*1e6, p[2]*1e6))
    e_pp, e_pw = restitution(alpha_pp), restitution(alpha_pw)
    with open(os.path.join(dem, "goldschmidt.liggghts"), "w") as f:
        f.write("# Written by goldschmidtSetup.py from the DPMFoam tutorial (units micro)\n")
        f.write("# type 1 particles, 2 walls, 3 the stand-ins of the symmetry planes\n")
        f.write("# e: LIGGGHTS' restitution whose damping is DPMFoam's alpha (pair %g, wall %g)\n" % (alpha_pp, alpha_pw))
        f.write("fix m1 all property/global youngsModulus peratomtype %g %g %g\n" % (E*1e-3, E_w*1e-3, E*1e-3))
        f.write("fix m2 all property/global poissonsRatio peratomtype %g %g %g\n" % (nu_p, nu_w, nu_p))
        f.write("fix m3 all property/global coefficientRestitution peratomtypepair 3 %.6f %.6f %.6f %.6f %.6f %.6f %.6f %.6f %.6f\n"
                % (e_pp, e_pw, e_sym, e_pw, e_pw, e_pw, e_sym, e_pw, e_sym))
        f.write("fix m4 all property/global coefficientFriction peratomtypepair 3 %g %g %g %g %g %g %g %g %g\n"
                % (mu_pp, mu_pw, mu_sym, mu_pw, mu_pw, mu_pw, mu_sym, mu_pw, mu_sym))
        f.write("variable yWall equal %g\nvariable zTop equal %g\nvariable symmetryWall equal %g\n"
                % (box[1][1], box[2][1], sym_wall))
        f.write("variable particleDiameter equal %g\nvariable particleDensity equal %g\n" % (2*r_um, rho_p*1e-3))
    values = {
        "inletVelocity": "%g" % inlet[2], "endTime": end_time, "writeInterval": write_interval,
        "deltaT": "%g" % delta_t, "epsilonMin": "%g" % (1.0 - alpha_max), "rho": "%g" % rho_f,
        "nu": "%g" % nu_f, "diameter": "%g" % d, "density": "%g" % rho_p,
        "timeStep": "%.10g" % (delta_t/substeps), "couplingInterval": "%d" % substeps,
    }
    for name in ("0.orig/U", "system/controlDict", "constant/couplingProperties"):
        path = os.path.join(case, name)
        text = open(path).read()
        for key, value in values.items():
            text = text.replace("@%s@" % key, value)
        left = re.search(r"@\w+@", text)
        if left:
            sys.exit("goldschmidtSetup: %s: %s was not filled in" % (path, left.group(0)))
        open(path, "w").write(text)
    print("goldschmidtSetup: %d spheres of %g m, %g kg/m^3; E %g Pa, nu %g; e pair %.4f (alpha %g), wall %.4f (alpha %g); "
          "DEM step %.4g s, %d per fluid step of %g s"
          % (len(pts), d, rho_p, E, nu_p, e_pp, alpha_pp, e_pw, alpha_pw, delta_t/substeps, substeps, delta_t))


if __name__ == "__main__":
    main()
