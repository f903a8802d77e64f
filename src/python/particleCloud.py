"""Read the particles colloidDEMFoam writes at each write time as an
OpenFOAM lagrangian cloud (<time>/lagrangian/particles/, or
processor<N>/<time>/lagrangian/particles/ of a parallel run that was not
reconstructed), ASCII format, with the standard library only.

A write time is named by its path <case>/<time>; read() returns the
particles of all processor folders of that time, sorted by particle id:
position, velocity [m/s], radius [m], id, nContacts, touchingParticle,
touchingWall, agglomerateSize (1 where the run wrote none), agglomerateId
(None where the run wrote none)."""
import glob
import os
import re

CLOUD = os.path.join("lagrangian", "particles")
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def _is_time(name):
    try:
        float(name)
        return True
    except ValueError:
        return False


def _cloud_dirs(path):
    """The cloud folders of one write time: reconstructed or per rank"""
    case, name = os.path.split(path)
    whole = os.path.join(path, CLOUD)
    if os.path.isdir(whole):
        return [whole]
    return sorted(glob.glob(os.path.join(case, "processor*", name, CLOUD)))


def write_times(case):
    """Write times with particles, in time order"""
    names = set()
    for root in [case] + glob.glob(os.path.join(case, "processor*")):
        for d in glob.glob(os.path.join(root, "*", CLOUD)):
            name = os.path.basename(os.path.dirname(os.path.dirname(d)))
            if _is_time(name):
                names.add(name)
    if not names:
        raise SystemExit("no particles (<time>/%s) in %s" % (CLOUD, case))
    return [os.path.join(case, n) for n in sorted(names, key=float)]


def latest(case):
    return write_times(case)[-1]


def time(path):
    """Physical time [s] of a write time"""
    return float(os.path.basename(path))


def list_values(path, width):
    """The numbers of an OpenFOAM list file, width numbers per element
    (a missing file on a rank without particles: none)"""
    if not os.path.exists(path):
        return []
    text = open(path).read()
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    start = text.index("FoamFile")
    text = text[text.index("}", start) + 1:]
    n = int(NUMBER.search(text).group(0))
    body = text[NUMBER.search(text).end():]
    if body.lstrip().startswith("{"):     # uniform list: n{value}
        value = [float(v) for v in NUMBER.findall(body[:body.index("}")])]
        flat = value*n
    else:
        flat = [float(v) for v in NUMBER.findall(body)][:width*n]
    if len(flat) != width*n:
        raise SystemExit("%s: %d numbers for %d entries of %d"
                         % (path, len(flat), n, width))
    return [flat[width*k:width*k + width] for k in range(n)]


def read(path):
    """Particles of one write time (all ranks), sorted by id"""
    rows = []
    for d in _cloud_dirs(path):
        pos = list_values(os.path.join(d, "positions"), 4)   # (x y z) celli
        ids = list_values(os.path.join(d, "origId"), 1)
        vel = list_values(os.path.join(d, "U"), 3)
        dia = list_values(os.path.join(d, "d"), 1)
        nc = list_values(os.path.join(d, "nContacts"), 1)
        tp = list_values(os.path.join(d, "touchingParticle"), 1)
        tw = list_values(os.path.join(d, "touchingWall"), 1)
        ag = list_values(os.path.join(d, "agglomerateSize"), 1) or [[1]]*len(pos)
        ai = list_values(os.path.join(d, "agglomerateId"), 1) or [[None]]*len(pos)
        for k in range(len(pos)):
            rows.append((int(ids[k][0]), pos[k][:3], vel[k], 0.5*dia[k][0],
                         int(nc[k][0]), int(tp[k][0]), int(tw[k][0]), int(ag[k][0]),
                         None if ai[k][0] is None else int(ai[k][0])))
    rows.sort(key=lambda row: row[0])
    keys = ["id", "position", "velocity", "radius", "nContacts",
            "touchingParticle", "touchingWall", "agglomerateSize", "agglomerateId"]
    return {key: [row[j] for row in rows] for j, key in enumerate(keys)}
