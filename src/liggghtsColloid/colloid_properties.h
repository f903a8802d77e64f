/* ----------------------------------------------------------------------
   colloidFoam LIGGGHTS plugin: reads the models' parameters from
   "fix property/global" through LIGGGHTS' property registry, converts them
   from run units to SI (factors from colloid_units.h) and checks each
   against its allowed range. A missing or out-of-range value stops the
   run with a message naming the property, the model, the value and the
   range.
------------------------------------------------------------------------- */

#ifndef COLLOID_PROPERTIES_H
#define COLLOID_PROPERTIES_H

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>
#include "error.h"
#include "fix_property_global.h"
#include "modify.h"
#include "property_registry.h"

namespace LIGGGHTS {
namespace Colloid {

// A per-atom-type-pair parameter in SI, indexed by LIGGGHTS type (from 1).
class TypePairTable
{
public:
    void resize(int maxType)
    {
        n_ = maxType + 1;
        values_.assign(n_*n_, 0.0);
    }
    double operator()(int itype, int jtype) const { return values_[itype*n_ + jtype]; }
    double & operator()(int itype, int jtype) { return values_[itype*n_ + jtype]; }
private:
    int n_ = 0;
    std::vector<double> values_;
};

class PropertyReader
{
public:
    // caller: the model's name as written in the input, used in messages
    PropertyReader(PropertyRegistry & registry, LAMMPS_NS::Modify *modify,
                   LAMMPS_NS::Error *error, const char *caller)
    : registry_(registry), modify_(modify), error_(error), caller_(caller)
    {}

    // scalar property in run units times toSI; lo <= SI value <= hi
    double scalar(const char *name, double toSI, double lo, double hi, const char *siUnit)
    {
        LAMMPS_NS::FixPropertyGlobal *fix = static_cast<LAMMPS_NS::FixPropertyGlobal*>(
            registry_.getGlobalProperty(name, "property/global", "scalar", 0, 0, caller_));
        if (!fix) return missing(name, "scalar");
        const double value = fix->compute_scalar()*toSI;
        check(name, "", value, lo, hi, siUnit);
        return value;
    }

    // as scalar(), but absent means fallback (given in SI); a property
    // defined under a name two edits or fewer from it is taken for a
    // misspelling and stops the run (else the default would be used
    // without a word)
    double optionalScalar(const char *name, double fallback, double toSI, double lo, double hi, const char *siUnit)
    {
        if (!modify_->find_fix_property(name, "property/global", "scalar", 0, 0, caller_, false))
        {
            misspelt(name);
            return fallback;
        }
        return scalar(name, toSI, lo, hi, siUnit);
    }

    // optional scalar choosing one of n variants 0..n-1 (absent: 0);
    // choices names them for the message
    int selector(const char *name, int n, const char *choices)
    {
        const double value = optionalScalar(name, 0.0, 1.0, -HUGE_VAL, HUGE_VAL, "");
        const int choice = static_cast<int>(value);
        if (choice != value || choice < 0 || choice >= n)
        {
            char msg[512];
            std::snprintf(msg, sizeof(msg), "%s: property/global '%s' is %g, allowed %s",
                caller_, name, value, choices);
            error_->all(FLERR, msg);
        }
        return choice;
    }

    // peratomtype property, one value per type (walls' types included),
    // indexed by type from 1
    void perType(const char *name, double toSI, double lo, double hi, const char *siUnit, std::vector<double> & values)
    {
        const int maxType = registry_.max_type();
        LAMMPS_NS::FixPropertyGlobal *fix = static_cast<LAMMPS_NS::FixPropertyGlobal*>(
            registry_.getGlobalProperty(name, "property/global", "peratomtype", maxType, 0, caller_));
        if (!fix)
        {
            missing(name, "peratomtype");
            return;
        }
        values.assign(maxType + 1, 0.0);
        for (int i = 1; i <= maxType; i++)
        {
            const double value = fix->compute_vector(i-1)*toSI;
            char where[64];
            std::snprintf(where, sizeof(where), " for type %d", i);
            check(name, where, value, lo, hi, siUnit);
            values[i] = value;
        }
    }

    // peratomtypepair property for every pair of types, walls' types included
    void typePair(const char *name, double toSI, double lo, double hi, const char *siUnit, TypePairTable & table)
    {
        const int maxType = registry_.max_type();
        LAMMPS_NS::FixPropertyGlobal *fix = static_cast<LAMMPS_NS::FixPropertyGlobal*>(
            registry_.getGlobalProperty(name, "property/global", "peratomtypepair", maxType, maxType, caller_));
        if (!fix)
        {
            missing(name, "peratomtypepair");
            return;
        }
        table.resize(maxType);
        for (int i = 1; i <= maxType; i++)
        {
            for (int j = 1; j <= maxType; j++)
            {
                const double value = fix->compute_array(i-1, j-1)*toSI;
                char where[64];
                std::snprintf(where, sizeof(where), " for types %d-%d", i, j);
                check(name, where, value, lo, hi, siUnit);
                table(i, j) = value;
            }
        }
    }

    // A kernel's parameter check (std::invalid_argument naming the kernel's
    // parameter, e.g. 'innerCutoff') turned into a run error naming the
    // property/global the parameter came from. names: kernel name, property
    // name, kernel name, property name, ..., NULL; itype, jtype: the type
    // pair whose values failed (0: not type-dependent)
    void kernelError(const std::invalid_argument & e, const char *const *names, int itype = 0, int jtype = 0)
    {
        std::string what = e.what();
        std::string property;
        for (const char *const *n = names; *n; n += 2)
        {
            if (what.find(std::string("'") + n[0] + "'") != std::string::npos)
            {
                property = n[1];
                break;
            }
        }
        std::string msg = std::string(caller_) + ": ";
        if (!property.empty())
            msg += "property/global '" + property + "' (in SI): ";
        msg += what;
        if (itype > 0)
            msg += " (types " + std::to_string(itype) + "-" + std::to_string(jtype) + ")";
        error_->all(FLERR, msg.c_str());
    }

    // make(i, j) for every type pair, i and j = 1..nTypes in row order (the
    // order of the models' per-pair kernel tables); a kernel's parameter
    // check (std::invalid_argument) stops the run as kernelError does,
    // naming the type pair being built
    template<class Make>
    void forEachTypePair(int nTypes, const char *const *names, Make make)
    {
        int ti = 0, tj = 0;
        try
        {
            for (ti = 1; ti <= nTypes; ti++)
                for (tj = 1; tj <= nTypes; tj++)
                    make(ti, tj);
        }
        catch (const std::invalid_argument & e)
        {
            kernelError(e, names, ti, tj);
        }
    }

private:
    void check(const char *name, const char *where, double value, double lo, double hi, const char *siUnit)
    {
        if (!(value >= lo && value <= hi))
        {
            char msg[512];
            std::snprintf(msg, sizeof(msg),
                "%s: property/global '%s'%s is %g %s (converted from run units), "
                "allowed range [%g, %g] %s",
                caller_, name, where, value, siUnit, lo, hi, siUnit);
            error_->all(FLERR, msg);
        }
    }

    // Stop if a scalar property/global is defined under a near miss of
    // name: one letter dropped, added, changed, or two swapped.  (LIGGGHTS
    // keeps the names of its property fixes private: the near misses are
    // looked up instead, about 2500 for a name of 20 letters, once.)
    void misspelt(const char *name)
    {
        const std::string n(name);
        std::vector<std::string> candidates;
        const std::string letters =
            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ";
        for (size_t i = 0; i < n.size(); i++)
        {
            candidates.push_back(n.substr(0, i) + n.substr(i + 1));
            if (i + 1 < n.size())
            {
                std::string t(n);
                std::swap(t[i], t[i + 1]);
                candidates.push_back(t);
            }
            for (const char c : letters)
            {
                if (c == n[i]) continue;
                std::string t(n);
                t[i] = c;
                candidates.push_back(t);
            }
        }
        for (size_t i = 0; i <= n.size(); i++)
        {
            for (const char c : letters)
            {
                candidates.push_back(n.substr(0, i) + c + n.substr(i));
            }
        }
        for (const std::string & c : candidates)
        {
            if (c == n || c.empty()) continue;
            if (modify_->find_fix_property(c.c_str(), "property/global", "scalar", 0, 0, caller_, false))
            {
                char msg[512];
                std::snprintf(msg, sizeof(msg),
                    "%s: property/global '%s' is read by no model; did you mean "
                    "'%s'? (optional: its default would be used)",
                    caller_, c.c_str(), name);
                error_->all(FLERR, msg);
            }
        }
    }

    // registry_.getGlobalProperty already stops the run on a missing
    // property; this guards against a library that returns NULL instead
    double missing(const char *name, const char *style)
    {
        char msg[256];
        std::snprintf(msg, sizeof(msg),
            "%s: needs 'fix ... all property/global %s %s ...'", caller_, name, style);
        error_->all(FLERR, msg);
        return 0.0;
    }

    PropertyRegistry & registry_;
    LAMMPS_NS::Modify *modify_;
    LAMMPS_NS::Error *error_;
    const char *caller_;
};

}
}

#endif
