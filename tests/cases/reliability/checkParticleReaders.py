#!/usr/bin/python3
"""The particles of a run's last write time, read by the tools a user
opens them with, must be the particles the solver says it wrote:
  - ParaView's OpenFOAM reader (vtkPOpenFOAMReader of Debian's VTK 9, the
    reader paraFoam and ParaView use): the reconstructed case and, for a
    parallel run, the decomposed case; every field of the cloud present;
  - foamToVTK's conversion (VTK/lagrangian/particles/particles_<i>.vtp);
  - src/python/particleCloud.py (the tests' and tutorials' reader).
Reference: the count of the solver's log line for that time ("written W
(lagrangian/particles)"), and the ids: unique, the same set in every
reader.  Positions of the readers agree within 1e-6 of the box (the VTK
files store 32-bit floats).

usage: checkParticleReaders.py caseDir time [decomposed]   (Debian's
/usr/bin/python3: python3-vtk9)
"""
import glob
import os
import re
import sys

import vtk
from vtk.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                '..', '..', '..', 'src', 'python'))
import particleCloud  # noqa: E402

FIELDS = ['U', 'd', 'origId', 'nContacts', 'touchingParticle', 'touchingWall']


def logged_count(case, time):
    """Particles written at the write time, from log.colloidDEMFoam"""
    log = open(os.path.join(case, 'log.colloidDEMFoam')).read()
    count = None
    for block in re.split(r'^Time = ', log, flags=re.M)[1:]:
        name = block.split()[0]
        m = re.search(r'written (\d+) \(lagrangian/particles\)', block)
        if m and float(name) == float(time):
            count = int(m.group(1))
    if count is None:
        raise SystemExit('no particle count for time %s in the log' % time)
    return count


def paraview_reader(case, time, decomposed):
    foam = os.path.join(case, 'case.foam')
    open(foam, 'a').close()
    # ParaView's reader, with its case type; one process (the decomposed
    # case needs a controller, a serial one here)
    controller = vtk.vtkDummyController()
    vtk.vtkMultiProcessController.SetGlobalController(controller)
    r = vtk.vtkPOpenFOAMReader()
    r.SetController(controller)
    r.SetFileName(foam)
    r.SetCaseType(0 if decomposed else 1)
    r.UpdateInformation()
    for i in range(r.GetNumberOfPatchArrays()):
        r.SetPatchArrayStatus(r.GetPatchArrayName(i), 0)
    r.SetPatchArrayStatus('lagrangian/particles', 1)
    r.EnableAllLagrangianArrays()
    r.UpdateTimeStep(float(time))
    r.Update()
    it = r.GetOutput().NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        block = it.GetCurrentDataObject()
        if block.GetNumberOfPoints() > 0 or block.IsA('vtkPolyData'):
            break
        it.GoToNextItem()
    if it.IsDoneWithTraversal():
        raise SystemExit('ParaView\'s reader found no lagrangian block')
    pd = block.GetPointData()
    names = [pd.GetArrayName(k) for k in range(pd.GetNumberOfArrays())]
    ids = vtk_to_numpy(pd.GetArray('origId')).tolist() if 'origId' in names else []
    points = vtk_to_numpy(block.GetPoints().GetData()).tolist() \
        if block.GetNumberOfPoints() else []
    return names, dict(zip(ids, points))


def foam_to_vtk(case):
    files = glob.glob(os.path.join(case, 'VTK', 'lagrangian', 'particles',
                                   '*.vtp'))
    if len(files) != 1:
        raise SystemExit('foamToVTK wrote %d particle files' % len(files))
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(files[0])
    reader.Update()
    out = reader.GetOutput()
    ids = vtk_to_numpy(out.GetPointData().GetArray('origId')).tolist()
    return dict(zip(ids, vtk_to_numpy(out.GetPoints().GetData()).tolist()))


def main():
    case, time = sys.argv[1], sys.argv[2]
    decomposed = len(sys.argv) > 3 and sys.argv[3] == 'decomposed'
    expected = logged_count(case, time)
    ok = True

    def check(good, text):
        nonlocal ok
        ok = ok and good
        print('%-66s %s' % (text, 'ok' if good else 'FAILED'))

    mine = particleCloud.read(os.path.join(case, time))
    ours = dict(zip(mine['id'], mine['position']))
    check(len(mine['id']) == expected == len(ours),
          'particleCloud.py: %d particles, %d unique ids (log: %d)'
          % (len(mine['id']), len(ours), expected))

    names, paraview = paraview_reader(case, time, False)
    missing = [f for f in FIELDS if f not in names]
    check(not missing and len(paraview) == expected,
          'ParaView reader, reconstructed: %d particles, fields missing: %s'
          % (len(paraview), missing or 'none'))
    if decomposed:
        _, pieces = paraview_reader(case, time, True)
        check(len(pieces) == expected and set(pieces) == set(ours),
              'ParaView reader, decomposed: %d particles' % len(pieces))

    converted = foam_to_vtk(case)
    check(len(converted) == expected, 'foamToVTK: %d particles'
          % len(converted))

    span = max(max(abs(c) for c in p) for p in ours.values())
    for name, other in (('ParaView reader', paraview),
                        ('foamToVTK', converted)):
        same = set(other) == set(ours)
        dx = max(max(abs(a - b) for a, b in zip(ours[i], other[i]))
                 for i in ours) if same else float('inf')
        check(same and dx <= 1e-6*span,
              '%s: same ids, positions within %.2g of the box'
              % (name, dx/span))
    print('PASS' if ok else 'FAIL')
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
