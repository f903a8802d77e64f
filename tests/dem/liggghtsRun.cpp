/*---------------------------------------------------------------------------*\
    colloidFoam DEM tests: see liggghtsRun.H.
\*---------------------------------------------------------------------------*/
#include "liggghtsRun.H"

#include "register_colloid_models.h"

#include "atom.h"
#include "input.h"
#include "lammps.h"
#include "library.h"
#include "update.h"
#include "variable.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace demTest
{

LiggghtsRun::LiggghtsRun()
:
    lmp_(nullptr)
{
    registerColloidModels();
    // LIGGGHTS writes to its screen unconditionally in places ("-screen
    // none" crashes mesh reading), so the screen goes to /dev/null and the
    // log, with any error message, to <test name>.log
    const ::testing::TestInfo* test =
        ::testing::UnitTest::GetInstance()->current_test_info();
    log_ = std::string(test ? test->name() : "liggghts") + ".log";
    const char* args[] =
        {"liggghts", "-log", log_.c_str(), "-echo", "log", "-screen", "/dev/null"};
    void* handle = nullptr;
    lammps_open_no_mpi(7, const_cast<char**>(args), &handle);
    lmp_ = static_cast<LAMMPS_NS::LAMMPS*>(handle);
}

LiggghtsRun::~LiggghtsRun()
{
    lammps_close(lmp_);
}

void LiggghtsRun::commands(const std::string& lines)
{
    std::istringstream in(lines);
    std::string line;
    while (std::getline(in, line))
    {
        lmp_->input->one(line.c_str());
    }
}

int LiggghtsRun::local(int id) const
{
    const int i = lmp_->atom->map(id);
    if (i < 0 || i >= lmp_->atom->nlocal)
    {
        throw std::runtime_error("atom " + std::to_string(id) + " is not a local atom");
    }
    return i;
}

const double* LiggghtsRun::x(int id) const { return lmp_->atom->x[local(id)]; }
const double* LiggghtsRun::v(int id) const { return lmp_->atom->v[local(id)]; }
const double* LiggghtsRun::f(int id) const { return lmp_->atom->f[local(id)]; }
const double* LiggghtsRun::omega(int id) const { return lmp_->atom->omega[local(id)]; }
double LiggghtsRun::mass(int id) const { return lmp_->atom->rmass[local(id)]; }
double LiggghtsRun::dt() const { return lmp_->update->dt; }
long LiggghtsRun::nAtoms() const { return static_cast<long>(lmp_->atom->natoms); }

double LiggghtsRun::evaluate(const std::string& expression)
{
    commands("variable liggghtsRunValue equal " + expression);
    LAMMPS_NS::Variable* variable = lmp_->input->variable;
    return variable->compute_equal(variable->find(const_cast<char*>("liggghtsRunValue")));
}

double LiggghtsRun::largestAllowedTimeStep() const
{
    if (lmp_->logfile) std::fflush(lmp_->logfile);
    std::ifstream in(log_);
    const std::string key = "(largest allowed dt: ";
    double smallest = -1;
    std::string line;
    while (std::getline(in, line))
    {
        const std::size_t at = line.find(key);
        if (at == std::string::npos) continue;
        const double dt = std::atof(line.c_str() + at + key.size());
        if (smallest < 0 || dt < smallest) smallest = dt;
    }
    return smallest;
}

std::string LiggghtsRun::waltonBraunMaterials()
{
    return
        "fix m1 all property/global loadingStiffness peratomtypepair 2 100 100 100 100\n"
        "fix m2 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5\n"
        "fix m3 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n";
}

std::string LiggghtsRun::twoSphereLubrication(double hIn, double hOut, double explicitRatio)
{
    std::ostringstream in;
    in.precision(17);
    in << "fix l2 all property/global lubricationInnerCutoff scalar " << hIn << "\n"
          "fix l3 all property/global lubricationOuterCutoff scalar " << hOut << "\n"
          "fix l4 all property/global lubricationFade scalar 1\n"
          "fix l5 all property/global lubricationFarField scalar 1\n"
          "fix l6 all property/global lubricationExplicitRatio scalar " << explicitRatio << "\n"
          "neighbor 0.1 bin\n"
          "neigh_modify delay 0\n"
          "pair_style gran model walton_braun tangential history cohesion colloid/lub timeStepCheck off\n"
          "pair_coeff * *\n";
    return in.str();
}

std::string LiggghtsRun::header(double halfBox, const std::string& boundary)
{
    const std::string b = std::to_string(halfBox);
    return
        "units micro\n"
        "atom_style granular\n"
        "atom_modify map array\n"
        "boundary " + boundary + "\n"
        "newton off\n"
        "communicate single vel yes\n"
        "region box block -" + b + " " + b + " -" + b + " " + b + " -" + b + " " + b + " units box\n"
        "create_box 2 box\n";
}

void writeSquareStl(const std::string& file, double halfSide, double zWall)
{
    std::ofstream out(file);
    const double a = halfSide;
    const double z = zWall;
    auto facet = [&](double x1, double y1, double x2, double y2, double x3, double y3)
    {
        out << "facet normal 0 0 1\nouter loop\n"
            << "vertex " << x1 << ' ' << y1 << ' ' << z << '\n'
            << "vertex " << x2 << ' ' << y2 << ' ' << z << '\n'
            << "vertex " << x3 << ' ' << y3 << ' ' << z << '\n'
            << "endloop\nendfacet\n";
    };
    out << "solid wall\n";
    facet(-a, -a, a, -a, a, a);
    facet(-a, -a, a, a, -a, a);
    out << "endsolid wall\n";
}

} // namespace demTest
