/*---------------------------------------------------------------------------*\
    colloidFoam DEM tests: see liggghtsProcess.H.
\*---------------------------------------------------------------------------*/
#include "liggghtsProcess.H"

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace demTest
{

ProcessResult runLiggghts(const std::string& name, const std::string& script)
{
    {
        std::ofstream in(name + ".in");
        in << script;
    }
    const std::string command =
        "LD_PRELOAD='" COLLOID_PLUGIN_LIBRARY "' '" LIGGGHTS_EXECUTABLE "' -in '"
      + name + ".in' -log '" + name + ".log' -echo none > '" + name + ".out' 2>&1";
    const int raw = std::system(command.c_str());

    ProcessResult result;
    result.status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
    std::ifstream out(name + ".out");
    std::ostringstream text;
    text << out.rdbuf();
    result.output = text.str();
    return result;
}

std::string boxHeader()
{
    return
        "units micro\n"
        "atom_style granular\n"
        "atom_modify map array\n"
        "boundary f f f\n"
        "newton off\n"
        "communicate single vel yes\n"
        "region box block -5 5 -5 5 -5 5 units box\n"
        "create_box 2 box\n"
        "neighbor 0.1 bin\n"
        "neigh_modify delay 0\n";
}

double numberAfter(const std::string& text, const std::string& marker)
{
    const std::size_t at = text.find(marker);
    if (at == std::string::npos) return std::nan("");
    const char* start = text.c_str() + at + marker.size();
    char* end = nullptr;
    const double value = std::strtod(start, &end);
    return end == start ? std::nan("") : value;
}

} // namespace demTest
