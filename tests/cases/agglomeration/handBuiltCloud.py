"""Hand-built particle clouds for the tests of the study's report
(testStudyWhere.py, testStudyVariants.py): a write time's
lagrangian/particles folder as colloidDEMFoam writes it, ASCII."""
import os
import shutil


def write_list(path, rows, fmt):
    """One field of the cloud: the rows, each formatted by fmt"""
    with open(path, "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class Cloud; object x; }\n")
        f.write("%d\n(\n" % len(rows))
        for r in rows:
            f.write(fmt % r + "\n")
        f.write(")\n")


def write_cloud(time_dir, parts, radius, R):
    """The particle cloud of a write time: parts (id, x, y, z,
    agglomerateSize[, agglomerateId]) [m], radius R [m] but those of the
    radius dict (by id); agglomerateId written if every part has one"""
    cloud = os.path.join(time_dir, "lagrangian", "particles")
    os.makedirs(cloud)
    write_list(os.path.join(cloud, "positions"), [(p[1], p[2], p[3], 0) for p in parts],
               "(%.15g %.15g %.15g) %d")
    write_list(os.path.join(cloud, "origId"), [(p[0],) for p in parts], "%d")
    write_list(os.path.join(cloud, "U"), [(0, 0, 0)]*len(parts), "(%g %g %g)")
    write_list(os.path.join(cloud, "d"), [(2*radius.get(p[0], R),) for p in parts], "%.15g")
    for name in ("nContacts", "touchingParticle", "touchingWall"):
        write_list(os.path.join(cloud, name), [(0,)]*len(parts), "%d")
    write_list(os.path.join(cloud, "agglomerateSize"), [(p[4],) for p in parts], "%d")
    if all(len(p) > 5 for p in parts):
        write_list(os.path.join(cloud, "agglomerateId"), [(p[5],) for p in parts], "%d")


def case_folder(root, case, contact_analysis="agglomerateGap 0.01;"):
    """A case folder for the report: the tutorial's (root: colloidFoam's
    folder) system/slotCoaterParameters and a constant/couplingProperties
    with these contactAnalysis entries"""
    os.makedirs(os.path.join(case, "system"))
    shutil.copy(os.path.join(root, "tutorials", "slotCoater", "system", "slotCoaterParameters"),
                os.path.join(case, "system"))
    os.makedirs(os.path.join(case, "constant"))
    with open(os.path.join(case, "constant", "couplingProperties"), "w") as f:
        f.write("contactAnalysis\n{\n    %s\n}\n" % contact_analysis)
