"""The cake of a finished filtration run, for consolidation: the particles
of its last write (<time>/lagrangian/particles) at rest in DEM/cake.data (LIGGGHTS
data file, units micro, the run's box up to just above the piston) and
the piston, a plate over the whole cross-section 0.05 um above the
highest particle, in DEM/piston.stl.  Prints the plate's height [um].

usage: makeCake.py runDir
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
# makeSuspension.py of the twoWay tutorials (also from a copy of this case)
sys.path.insert(0, os.path.join(os.environ.get(
    'COLLOIDFOAM_TUTORIALS', os.path.join(here, '..')), 'twoWay'))
from filtrationResults import read_particles, eval_entry  # noqa: E402
import particleCloud  # noqa: E402
from makeSuspension import write_data  # noqa: E402


def main():
    run = sys.argv[1]
    time, pos, vel, rad = read_particles(particleCloud.latest(run))
    um = 1e6
    width = eval_entry(os.path.join(run, 'system', 'filtrationParameters'),
                       'width')
    # each sphere's diameter as set (particleDiameter, or fineDiameter
    # for the fines): not the cloud's written digits
    params = os.path.join(run, 'system', 'filtrationParameters')
    sizes = [eval_entry(params, 'particleDiameter')*um]
    if 'fineDiameter' in open(params).read():    # not in older runs
        sizes.append(eval_entry(params, 'fineDiameter')*um)
    d = [min(sizes, key=lambda s: abs(s - 2*r*um)) for r in rad]
    top = max((p[1] + r)*um for p, r in zip(pos, rad))
    piston = top + 0.05
    pts = [(p[0]*um % width, p[1]*um, p[2]*um % width) for p in pos]
    write_data(os.path.join(run, 'DEM', 'cake.data'), pts, d,
               (width, piston + 1.0, width),
               'the cake at %g s, %d spheres (makeCake.py)' % (time, len(pts)))
    with open(os.path.join(run, 'DEM', 'piston.stl'), 'w') as f:
        f.write('solid piston\n')
        for tri in (((0, 0), (width, 0), (width, width)),
                    ((0, 0), (width, width), (0, width))):
            f.write('facet normal 0 -1 0\nouter loop\n')
            for x, z in tri:
                f.write('vertex %.9g %.9g %.9g\n' % (x, piston, z))
            f.write('endloop\nendfacet\n')
        f.write('endsolid piston\n')
    print('%.9g' % piston)


if __name__ == '__main__':
    main()
