#!/usr/bin/env python3
"""The start-up report of the expected error (runStartupReport.sh) against
the study's own table, errorStudy.csv:

  onRung:    the line for demTimeStep names the case's step (1e-8 s), and
             its error in each quantity and its run time equal that rung's
             row of errorStudy.csv to the 3 digits printed (relative 0.5 %);
             for each tolerance it names the rung that the CSV gives as the
             cheapest ok rung within it and its run time over this one's
             (or "no rung" where none is within it);
  offLadder: the case (4e-9 s) is on no rung: "not measured", naming the
             rungs;
  noStudy:   "none measured for this case";
  missingEntry: "not measured", naming the file and the missing entry;
  corrupt:   "cannot be used", and the run goes to its end;
  otherDensity, otherDrag: the case is not the study's context (a number,
             a word): "none measured for this case", naming the entry and
             both values, and no setting's error;
  contextEntryMissing: the study's context names an entry this case does
             not have: "none measured for this case", naming it.

usage: checkStartupReport.py studyOutputDir workDir
"""
import csv
import os
import re
import sys

DIGITS = 0.005      # printed with 3 significant digits


def close(a, b):
    return abs(a - b) <= DIGITS*max(abs(a), abs(b)) + 1e-300


def report_lines(log):
    text = open(log).read()
    m = re.search(r"^(Expected error.*?)\n\s*\n", text, re.M | re.S)
    return m.group(1).splitlines() if m else []


def main():
    out, work = sys.argv[1:3]
    rows = [r for r in csv.DictReader(open(os.path.join(out, "errorStudy.csv")))
            if r["setting"] == "demTimeStep"]
    quantities = [h[:-len("_error")] for h in rows[0] if h.endswith("_error")]
    ok = True

    def check(what, good):
        nonlocal ok
        print("%s: %s" % (what, "ok" if good else "FAIL"))
        ok = ok and good

    # onRung
    lines = report_lines(os.path.join(work, "onRung", "log.colloidDEMFoam"))
    print("\n".join(lines))
    line = next((l for l in lines if l.strip().startswith("demTimeStep")), "")
    m = re.match(r"\s*demTimeStep (\S+): (.*); run time (\S+) s(.*)$", line)
    check("onRung: a demTimeStep line with value and run time", m is not None)
    if m:
        value = float(m.group(1))
        check("onRung: the case's step 1e-08 s named", close(value, 1e-8))
        row = next(r for r in rows if close(float(r["value"]), 1e-8))
        for q in quantities:
            p = re.search(r"\b%s (\S+) %% \(([^)]*)\)" % q, m.group(2))
            check("onRung: %s printed" % q, p is not None)
            if p:
                check("onRung: %s error %s %% against the CSV's %.4g %%"
                      % (q, p.group(1), 100*float(row[q + "_error"])),
                      close(float(p.group(1))/100, float(row[q + "_error"])))
                check("onRung: %s source '%s' against the CSV's '%s'"
                      % (q, p.group(2), row[q + "_errorSource"]),
                      p.group(2) == row[q + "_errorSource"])
        cost = float(row["cost_s"])
        check("onRung: run time %s s against the CSV's %.4g s" % (m.group(3), cost),
              close(float(m.group(3)), cost))
        for tol in (0.01, 0.05):
            within = [r for r in rows if r["status"] == "ok" and
                      all(r[q + "_error"] not in ("", "–") and float(r[q + "_error"]) <= tol
                          for q in quantities)]
            if not within:
                check("onRung: cheapest within %g %%: no rung (CSV: none)" % (100*tol),
                      "cheapest within %g %%: no rung" % (100*tol) in m.group(4))
                continue
            best = min(within, key=lambda r: float(r["cost_s"]))
            p = re.search(r"cheapest within %g %%: (\S+) \((\S+) x this run time\)" % (100*tol),
                          m.group(4))
            check("onRung: cheapest within %g %%: %s (CSV: %s)"
                  % (100*tol, p and p.group(1), best["value"]),
                  p is not None and close(float(p.group(1)), float(best["value"]))
                  and close(float(p.group(2)), float(best["cost_s"])/cost))

    # offLadder
    lines = report_lines(os.path.join(work, "offLadder", "log.colloidDEMFoam"))
    print("\n".join(lines))
    log = open(os.path.join(work, "offLadder", "log.colloidDEMFoam")).read()
    check("offLadder: the run's DEM step is 4e-09 s", "DEM step 4e-09 s" in log)
    check("offLadder: demTimeStep not measured, the rungs named",
          any(re.match(r"\s*demTimeStep: not measured \(this case's value is none of the rungs "
                       r"2e-08 1e-08 5e-09 2.5e-09\)", l) for l in lines))

    # noStudy
    lines = report_lines(os.path.join(work, "noStudy", "log.colloidDEMFoam"))
    print("\n".join(lines))
    check("noStudy: none measured for this case",
          any(l.startswith("Expected error: none measured for this case") for l in lines))

    # missingEntry
    lines = report_lines(os.path.join(work, "missingEntry", "log.colloidDEMFoam"))
    print("\n".join(lines))
    check("missingEntry: not measured, the file and entry named",
          any(re.match(r"\s*demTimeStep: not measured \(constant/couplingProperties has no "
                       r"entry DEM/noSuchEntry\)", l) for l in lines))

    # corrupt
    log = open(os.path.join(work, "corrupt", "log.colloidDEMFoam")).read()
    print("\n".join(l for l in log.splitlines() if l.startswith("Expected error")))
    check("corrupt: reported as unusable",
          re.search(r"^Expected error: errorStudy/measuredErrors cannot be used", log, re.M)
          is not None)
    check("corrupt: the run went to its end", re.search(r"^End\s*$", log, re.M) is not None)

    # otherDensity, otherDrag
    for variant, why in (
            ("otherDensity", "the study's constant/couplingProperties entry particles/density "
                             "is 2500, this case's 2600)"),
            ("otherDrag", "the study's constant/couplingProperties entry dragModel "
                          "is schillerNaumann, this case's stokes)"),
            ("contextEntryMissing", ": constant/couplingProperties has no entry particles/noSuchEntry)")):
        lines = report_lines(os.path.join(work, variant, "log.colloidDEMFoam"))
        print("\n".join(lines))
        check("%s: none measured for this case, %s" % (variant, why),
              any(l.startswith("Expected error: none measured for this case") and l.endswith(why)
                  for l in lines))
        check("%s: no setting's error printed" % variant,
              not any(l.strip().startswith("demTimeStep") for l in lines))

    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
