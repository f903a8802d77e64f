"""Read the particle files colloidDEMFoam writes (legacy ASCII VTK
polydata): positions and point data by name."""
import glob
import os
import re


def all_files(case):
    """Particle files of a case, in time order"""
    files = glob.glob(os.path.join(case, "VTK", "particles_*.vtk"))
    if not files:
        raise SystemExit("no particle files in %s/VTK" % case)
    return sorted(files, key=lambda f: int(re.search(r"_(\d+)\.vtk$", f).group(1)))


def latest(case):
    return all_files(case)[-1]


def time(path):
    """Physical time [s] from the file's title line"""
    with open(path) as f:
        f.readline()
        return float(re.search(r"time (\S+) s", f.readline()).group(1))


def read(path):
    tok = open(path).read().split()
    data = {}
    i = tok.index("POINTS")
    n = int(tok[i + 1])
    flat = [float(t) for t in tok[i + 3:i + 3 + 3*n]]
    data["position"] = [flat[3*k:3*k + 3] for k in range(n)]
    i = tok.index("VECTORS")
    flat = [float(t) for t in tok[i + 3:i + 3 + 3*n]]
    data[tok[i + 1]] = [flat[3*k:3*k + 3] for k in range(n)]
    for j, t in enumerate(tok):
        if t == "SCALARS":
            start = j + 6   # SCALARS name type 1 LOOKUP_TABLE default
            data[tok[j + 1]] = [float(v) for v in tok[start:start + n]]
    return data
