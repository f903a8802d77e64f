#include "particleExchange.H"
#include "PstreamBuffers.H"
#include "Random.H"

Foam::particleExchange::particleExchange
(
    const fvMesh& mesh,
    const particleLocator& locator
)
:
    mesh_(mesh),
    locator_(locator),
    procBb_(Pstream::nProcs())
{
    // Slightly enlarged so that points on the mesh boundary are inside
    treeBoundBox bb(mesh_.points());
    Random rndGen(4711);
    bb = bb.extend(rndGen, 1e-6);
    procBb_[Pstream::myProcNo()] = bb;
    Pstream::gatherList(procBb_);
    Pstream::scatterList(procBb_);
}


void Foam::particleExchange::answer
(
    const List<point>& p,
    const labelList& hint,
    const scalarList& maxWallDist,
    labelList& cell,
    scalarList& wallDist
) const
{
    cell.setSize(p.size());
    wallDist.setSize(p.size());

    forAll(p, i)
    {
        answerOne(p[i], hint[i], maxWallDist[i], cell[i], wallDist[i]);
    }
}


void Foam::particleExchange::answerOne
(
    const point& p,
    const label hint,
    const scalar maxWallDist,
    label& cell,
    scalar& wallDist
) const
{
    cell = locator_.findCell(p, hint);
    wallDist =
        (cell >= 0 && maxWallDist > 0)
      ? locator_.wallDistance(p, cell, maxWallDist)
      : GREAT;
}


void Foam::particleExchange::exchange
(
    const List<List<point>>& p,
    const List<labelList>& hint,
    const List<scalarList>& maxWallDist,
    List<labelList>& cell,
    List<scalarList>& wallDist
) const
{
    const label nProcs = Pstream::nProcs();
    cell.setSize(nProcs);
    wallDist.setSize(nProcs);

    // This rank's own queries are answered here, not sent to itself
    // through the buffers (most particles stay on their rank)
    const label me = Pstream::myProcNo();
    answer(p[me], hint[me], maxWallDist[me], cell[me], wallDist[me]);
    if (!Pstream::parRun())
    {
        return;
    }

    // Queries out: only to other ranks that have some
    PstreamBuffers queries(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (proci != me && p[proci].size())
        {
            UOPstream os(proci, queries);
            os << p[proci] << hint[proci] << maxWallDist[proci];
        }
    }
    labelList querySizes;
    queries.finishedSends(querySizes);

    // Answers back to the ranks that asked
    PstreamBuffers answers(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (proci != me && querySizes[proci])
        {
            UIPstream is(proci, queries);
            List<point> qp(is);
            labelList qHint(is);
            scalarList qMax(is);

            labelList aCell;
            scalarList aWall;
            answer(qp, qHint, qMax, aCell, aWall);

            UOPstream os(proci, answers);
            os << aCell << aWall;
        }
    }
    labelList answerSizes;
    answers.finishedSends(answerSizes);

    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (proci != me && answerSizes[proci])
        {
            UIPstream is(proci, answers);
            is >> cell[proci] >> wallDist[proci];
        }
    }
}


void Foam::particleExchange::locate
(
    const List<point>& p,
    const labelList& prevProc,
    const labelList& prevCell,
    const scalarList& maxWallDist,
    labelList& proc,
    labelList& cell,
    scalarList& wallDist
) const
{
    const label nProcs = Pstream::nProcs();
    const label n = p.size();

    proc.setSize(n, -1);
    proc = -1;
    cell.setSize(n, -1);
    cell = -1;
    wallDist.setSize(n, GREAT);
    wallDist = GREAT;

    // Rank tried in the first round, per particle
    labelList tried(n, -1);

    // Round 1: previous owner with its cell as hint, else first candidate
    // box.  Round 2: the remaining candidate boxes, global search.
    for (label round = 0; round < 2; ++round)
    {
        List<DynamicList<point>> qp(nProcs);
        List<DynamicList<label>> qHint(nProcs);
        List<DynamicList<scalar>> qMax(nProcs);
        List<DynamicList<label>> qIndex(nProcs);

        for (label i = 0; i < n; ++i)
        {
            if (round == 0)
            {
                label target = -1;
                label hint = -1;
                if (prevProc[i] >= 0 && prevProc[i] < nProcs)
                {
                    target = prevProc[i];
                    hint = prevCell[i];
                }
                else if (procBb_[Pstream::myProcNo()].contains(p[i]))
                {
                    target = Pstream::myProcNo();
                }
                else
                {
                    forAll(procBb_, proci)
                    {
                        if (procBb_[proci].contains(p[i]))
                        {
                            target = proci;
                            break;
                        }
                    }
                }
                if (target == Pstream::myProcNo())
                {
                    // Most particles: answered here, no query list
                    tried[i] = target;
                    answerOne(p[i], hint, maxWallDist[i], cell[i], wallDist[i]);
                    if (cell[i] >= 0)
                    {
                        proc[i] = target;
                    }
                }
                else if (target >= 0)
                {
                    tried[i] = target;
                    qp[target].append(p[i]);
                    qHint[target].append(hint);
                    qMax[target].append(maxWallDist[i]);
                    qIndex[target].append(i);
                }
            }
            else if (cell[i] < 0)
            {
                forAll(procBb_, proci)
                {
                    if (proci != tried[i] && procBb_[proci].contains(p[i]))
                    {
                        qp[proci].append(p[i]);
                        qHint[proci].append(-1);
                        qMax[proci].append(maxWallDist[i]);
                        qIndex[proci].append(i);
                    }
                }
            }
        }

        // A collective call: every rank takes part in every round
        List<List<point>> sendP(nProcs);
        List<labelList> sendHint(nProcs);
        List<scalarList> sendMax(nProcs);
        for (label proci = 0; proci < nProcs; ++proci)
        {
            sendP[proci].transfer(qp[proci]);
            sendHint[proci].transfer(qHint[proci]);
            sendMax[proci].transfer(qMax[proci]);
        }

        List<labelList> aCell;
        List<scalarList> aWall;
        exchange(sendP, sendHint, sendMax, aCell, aWall);

        // Lowest rank wins where a point on a processor face is found twice
        // (in the second round; in the first each particle asks one rank)
        for (label proci = 0; proci < nProcs; ++proci)
        {
            const labelList& idx = qIndex[proci];
            forAll(idx, k)
            {
                const label i = idx[k];
                if (aCell[proci][k] >= 0 && cell[i] < 0)
                {
                    proc[i] = proci;
                    cell[i] = aCell[proci][k];
                    wallDist[i] = aWall[proci][k];
                }
            }
        }

        // One rank: a second round could only repeat the global search.
        // Several: skip it when every particle was found where expected.
        if
        (
            !Pstream::parRun()
         || !returnReduce(cell.found(-1), orOp<bool>())
        )
        {
            break;
        }
    }
}
