#include "couplingProperties.H"
#include "Time.H"
#include "OSspecific.H"
#include "keywordCheck.H"
#include "Tuple2.H"
#include "Pair.H"
#include "colloidModels/exchangeStability.H"

const Foam::dictionary& Foam::couplingProperties::requiredSubDict
(
    const dictionary& dict,
    const word& key
)
{
    if (!dict.isDict(key))
    {
        FatalIOErrorInFunction(dict)
            << "Missing sub-dictionary '" << key << "' in " << dict.name()
            << exit(FatalIOError);
    }
    return dict.subDict(key);
}


Foam::scalar Foam::couplingProperties::positiveScalar
(
    const dictionary& dict,
    const word& key
)
{
    if (!dict.found(key))
    {
        FatalIOErrorInFunction(dict)
            << "Missing keyword '" << key << "' in " << dict.name()
            << " (allowed range: > 0)"
            << exit(FatalIOError);
    }

    const scalar value = dict.get<scalar>(key);

    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << key << "' in " << dict.name() << " is "
            << value << "; allowed range: > 0"
            << exit(FatalIOError);
    }
    return value;
}


Foam::couplingProperties::couplingProperties(const objectRegistry& obr)
:
    IOdictionary
    (
        IOobject
        (
            "couplingProperties",
            obr.time().constant(),
            obr,
            IOobject::MUST_READ_IF_MODIFIED,
            IOobject::NO_WRITE
        )
    ),
    rhoFluid_(0),
    muFluid_(0),
    particleDiameter_(0),
    smallestDiameter_(0),
    largestDiameter_(0),
    particleDensity_(0),
    demTimeStep_(0),
    couplingInterval_(0),
    demScreen_(false),
    allowLostParticles_(false),
    twoWay_(false),
    modelB_(false),
    epsilonMin_(1),
    freeFluidFraction_(colloid::exchangeStability::looseFluidFraction),
    kernel_("satellite"),
    kernelRadius_(0),
    selfInducedVelocity_(false),
    clipFluidFraction_(false),
    contactAnalysis_(false),
    contactInterval_(1),
    touchingGap_(0.01),
    releaseGap_(0.01),
    agglomerateGap_(0.01),
    brownianTemperature_(0),
    brownianSeed_(0)
{
    const dictionary& dict = *this;

    if (!dict.found("couplingMode"))
    {
        FatalIOErrorInFunction(dict)
            << "Missing keyword 'couplingMode' in " << dict.name()
            << " (allowed: oneWay twoWay)" << exit(FatalIOError);
    }
    const word mode(dict.get<word>("couplingMode"));
    if (mode != "oneWay" && mode != "twoWay")
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'couplingMode' in " << dict.name() << " is '"
            << mode << "'; allowed: oneWay twoWay" << exit(FatalIOError);
    }
    twoWay_ = (mode == "twoWay");

    if (twoWay_)
    {
        const dictionary& tw = requiredSubDict(dict, "twoWay");
        if (!tw.found("modelType"))
        {
            FatalIOErrorInFunction(tw)
                << "Missing keyword 'modelType' in " << tw.name()
                << " (allowed: A B)" << exit(FatalIOError);
        }
        const word model(tw.get<word>("modelType"));
        if (model != "A" && model != "B")
        {
            FatalIOErrorInFunction(tw)
                << "Keyword 'modelType' in " << tw.name() << " is '"
                << model << "'; allowed: A (fluid -eps grad p, particles"
                << " feel drag and pressure gradient) or B (fluid"
                << " -grad p, particles feel drag/eps)"
                << exit(FatalIOError);
        }
        modelB_ = (model == "B");

        if (!tw.found("epsilonMin"))
        {
            FatalIOErrorInFunction(tw)
                << "Missing keyword 'epsilonMin' in " << tw.name()
                << " (allowed range: (0, 1))" << exit(FatalIOError);
        }
        epsilonMin_ = tw.get<scalar>("epsilonMin");
        if (!(epsilonMin_ > 0 && epsilonMin_ < 1))
        {
            FatalIOErrorInFunction(tw)
                << "Keyword 'epsilonMin' in " << tw.name() << " is "
                << epsilonMin_ << "; allowed range: (0, 1)"
                << exit(FatalIOError);
        }

        freeFluidFraction_ = tw.getOrDefault<scalar>
        (
            "freeFluidFraction",
            colloid::exchangeStability::looseFluidFraction
        );
        if (!(freeFluidFraction_ > 0 && freeFluidFraction_ <= 1))
        {
            FatalIOErrorInFunction(tw)
                << "Keyword 'freeFluidFraction' in " << tw.name() << " is "
                << freeFluidFraction_ << "; allowed range: (0, 1] (default "
                << colloid::exchangeStability::looseFluidFraction
                << ", random loose packing)" << exit(FatalIOError);
        }

        kernel_ = tw.getOrDefault<word>("kernel", "satellite");
        kernelRadius_ = tw.getOrDefault<scalar>("kernelRadius", 0);
        if (kernel_ != "satellite" && kernelRadius_ != 0)
        {
            FatalIOErrorInFunction(tw)
                << "Keyword 'kernelRadius' in " << tw.name() << " is "
                << kernelRadius_ << " m, but 'kernel' is '" << kernel_
                << "', whose support is set by the mesh; allowed: 0 (or"
                << " no kernelRadius), or kernel satellite"
                << exit(FatalIOError);
        }
        if (kernelRadius_ < 0)
        {
            FatalIOErrorInFunction(tw)
                << "Keyword 'kernelRadius' in " << tw.name() << " is "
                << kernelRadius_ << "; allowed range: >= 0 [m] (0: the"
                << " particle's own radius)" << exit(FatalIOError);
        }
        selfInducedVelocity_ =
            tw.getOrDefault<bool>("selfInducedVelocity", false);
        if (selfInducedVelocity_ && !(kernelRadius_ > 0))
        {
            FatalIOErrorInFunction(tw)
                << "Keyword 'selfInducedVelocity' in " << tw.name()
                << " is 'yes' but 'kernelRadius' is " << kernelRadius_
                << ": the correction F/(5 pi mu R) needs the satellite"
                << " kernel (kernel satellite) with a kernel radius R > 0"
                << " [m], at least two cell sizes" << exit(FatalIOError);
        }
        clipFluidFraction_ =
            tw.getOrDefault<bool>("clipFluidFraction", false);
    }

    // Fluid: mu directly, or nu times rho
    const dictionary& fluid = requiredSubDict(dict, "fluid");
    rhoFluid_ = positiveScalar(fluid, "rho");
    if (fluid.found("mu") && fluid.found("nu"))
    {
        FatalIOErrorInFunction(fluid)
            << "Give either 'mu' or 'nu' in " << fluid.name() << ", not both"
            << exit(FatalIOError);
    }
    if (fluid.found("nu"))
    {
        muFluid_ = rhoFluid_*positiveScalar(fluid, "nu");
    }
    else
    {
        muFluid_ = positiveScalar(fluid, "mu");
    }

    const dictionary& particles = requiredSubDict(dict, "particles");
    particleDiameter_ = positiveScalar(particles, "diameter");
    particleDensity_ = positiveScalar(particles, "density");
    smallestDiameter_ = largestDiameter_ = particleDiameter_;
    if (particles.found("diameterRange"))
    {
        const Pair<scalar> range = particles.get<Pair<scalar>>("diameterRange");
        if
        (
            !(range.first() > 0)
         || !(range.first() <= particleDiameter_)
         || !(particleDiameter_ <= range.second())
        )
        {
            FatalIOErrorInFunction(particles)
                << "Keyword 'diameterRange' in " << particles.name()
                << " is (" << range.first() << " " << range.second()
                << ") m; allowed: (smallest largest) with 0 < smallest <="
                << " diameter (" << particleDiameter_ << " m) <= largest"
                << exit(FatalIOError);
        }
        smallestDiameter_ = range.first();
        largestDiameter_ = range.second();
    }

    const dictionary& dem = requiredSubDict(dict, "DEM");
    if (!dem.found("script"))
    {
        FatalIOErrorInFunction(dem)
            << "Missing keyword 'script' in " << dem.name()
            << " (a LIGGGHTS input file, relative to the case)"
            << exit(FatalIOError);
    }
    demScript_ = dem.get<fileName>("script");
    demScript_.expand();
    if (!demScript_.isAbsolute())
    {
        demScript_ = obr.time().globalPath()/demScript_;
    }
    if (!isFile(demScript_))
    {
        FatalIOErrorInFunction(dem)
            << "Keyword 'script' in " << dem.name() << ": file "
            << demScript_ << " does not exist" << exit(FatalIOError);
    }

    demTimeStep_ = positiveScalar(dem, "timeStep");

    if (!dem.found("couplingInterval"))
    {
        FatalIOErrorInFunction(dem)
            << "Missing keyword 'couplingInterval' in " << dem.name()
            << " (allowed range: integer >= 1)" << exit(FatalIOError);
    }
    couplingInterval_ = dem.get<label>("couplingInterval");
    if (couplingInterval_ < 1)
    {
        FatalIOErrorInFunction(dem)
            << "Keyword 'couplingInterval' in " << dem.name() << " is "
            << couplingInterval_ << "; allowed range: integer >= 1"
            << exit(FatalIOError);
    }

    demScreen_ = dem.getOrDefault<bool>("screen", false);
    allowLostParticles_ = dem.getOrDefault<bool>("allowLostParticles", false);

    // Contacts and agglomerates: gaps as fractions of the smaller radius
    contactAnalysis_ = dict.found("contactAnalysis");
    if (contactAnalysis_)
    {
        const dictionary& ca = requiredSubDict(dict, "contactAnalysis");
        contactInterval_ = ca.getOrDefault<label>("interval", 1);
        if (contactInterval_ < 1)
        {
            FatalIOErrorInFunction(ca)
                << "Keyword 'interval' in " << ca.name() << " is "
                << contactInterval_ << "; allowed range: integer >= 1"
                << " (coupling steps between analyses)" << exit(FatalIOError);
        }
        // the release and agglomerate gaps default to the touching gap
        touchingGap_ = ca.getOrDefault<scalar>("touchingGap", 0.01);
        releaseGap_ = ca.getOrDefault<scalar>("releaseGap", touchingGap_);
        agglomerateGap_ =
            ca.getOrDefault<scalar>("agglomerateGap", touchingGap_);
        const Tuple2<word, scalar> gaps[] =
        {
            {"touchingGap", touchingGap_},
            {"releaseGap", releaseGap_},
            {"agglomerateGap", agglomerateGap_}
        };
        for (const Tuple2<word, scalar>& gap : gaps)
        {
            const bool release = gap.first() == "releaseGap";
            const scalar lowest = release ? touchingGap_ : 0;
            if (!(gap.second() >= lowest && gap.second() < 1))
            {
                FatalIOErrorInFunction(ca)
                    << "Keyword '" << gap.first() << "' in " << ca.name()
                    << " is " << gap.second() << "; allowed range: ["
                    << lowest << ", 1) (a gap as a fraction of the smaller"
                    << " radius" << (release ? "; not below touchingGap" : "")
                    << ")" << exit(FatalIOError);
            }
        }
        keywordCheck
        (
            ca,
            {"interval", "touchingGap", "releaseGap", "agglomerateGap"},
            true
        );
    }

    // Brownian motion: the DEM's drag update adds the random force
    if (dict.found("brownian"))
    {
        const dictionary& br = requiredSubDict(dict, "brownian");
        brownianTemperature_ = positiveScalar(br, "temperature");
        if (brownianTemperature_ >= 1e4)
        {
            FatalIOErrorInFunction(br)
                << "Keyword 'temperature' in " << br.name() << " is "
                << brownianTemperature_ << "; allowed range: (0, 1e4) K"
                << exit(FatalIOError);
        }
        if (!br.found("seed"))
        {
            FatalIOErrorInFunction(br)
                << "Missing keyword 'seed' in " << br.name()
                << " (allowed range: integer 1 to 2e9; the same seed gives"
                << " the same run)" << exit(FatalIOError);
        }
        brownianSeed_ = br.get<label>("seed");
        if (brownianSeed_ < 1)
        {
            FatalIOErrorInFunction(br)
                << "Keyword 'seed' in " << br.name() << " is "
                << brownianSeed_ << "; allowed range: integer 1 to 2e9"
                << exit(FatalIOError);
        }
        keywordCheck(br, {"temperature", "seed"}, true);
    }

    // Misspelt keywords: the sub-dictionaries hold only these settings;
    // the top level may also hold a case's #included parameters
    keywordCheck
    (
        dict,
        {"couplingMode", "dragModel", "forceModels", "twoWay", "fluid",
         "particles", "DEM", "contactAnalysis", "brownian", "feed"},
        false
    );
    if (twoWay_)
    {
        keywordCheck
        (
            dict.subDict("twoWay"),
            {"modelType", "epsilonMin", "freeFluidFraction", "kernel",
             "kernelRadius", "selfInducedVelocity", "clipFluidFraction"},
            true
        );
    }
    keywordCheck(fluid, {"rho", "mu", "nu"}, true);
    keywordCheck(particles, {"diameter", "density", "diameterRange"}, true);
    keywordCheck
    (
        dem,
        {"script", "timeStep", "couplingInterval", "screen",
         "allowLostParticles"},
        true
    );
}
