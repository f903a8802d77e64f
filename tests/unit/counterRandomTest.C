/*---------------------------------------------------------------------------*\
    Unit tests of counterRandom.H, the random numbers of the Brownian forces.

    References: the normal distribution function Phi(x) = erfc(-x/sqrt 2)/2
    of the C library, inverted here by bisection; the moments and the
    Kolmogorov-Smirnov bound of a sample of independent normal numbers.
\*---------------------------------------------------------------------------*/
#include "counterRandom.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace colloid::counterRandom;

namespace
{

//- The lower-tail quantile x < 0 with Phi(x) = t <= 1/2, by bisection on
//  erfc, which is accurate to relative round-off for small t
double lowerQuantile(double t)
{
    double lo = -40, hi = 0;
    for (int i = 0; i < 200; ++i)
    {
        const double mid = 0.5*(lo + hi);
        if (0.5*std::erfc(-mid/std::sqrt(2.0)) < t)
        {
            lo = mid;
        }
        else
        {
            hi = mid;
        }
    }
    return 0.5*(lo + hi);
}

//- Phi(x)
double normalCdf(double x)
{
    return 0.5*std::erfc(-x/std::sqrt(2.0));
}

} // namespace


// Acklam's stated accuracy: relative error below 1.15e-9 over (0, 1),
// checked at probabilities from 1e-300 to 1/2 and their complements
// (the central region, its edges at 0.02425 and both tails)
TEST(counterRandom, normalQuantileAgainstErfc)
{
    std::vector<double> probabilities;
    for (double e = -300; e <= -1; e += 0.25)
    {
        probabilities.push_back(std::pow(10.0, e));
    }
    for (double t = 0.01; t < 0.5; t += 0.0025)
    {
        probabilities.push_back(t);
    }
    for (double t : {0.02425 - 1e-12, 0.02425, 0.02425 + 1e-12, 0.5 - 1e-9})
    {
        probabilities.push_back(t);
    }
    for (double t : probabilities)
    {
        const double reference = lowerQuantile(t);
        const double tolerance = 1.2e-9*std::fabs(reference) + 1e-15;
        EXPECT_NEAR(normalQuantile(t), reference, tolerance) << "p = " << t;
        if (t > 1e-16)
        {
            // the upper tail by symmetry, at the probability p = 1 - t as
            // rounded to a double: its tail 1 - p is exact (Sterbenz)
            const double p = 1 - t;
            const double upper = -lowerQuantile(1 - p);
            EXPECT_NEAR
            (
                normalQuantile(p), upper, 1.2e-9*std::fabs(upper) + 1e-15
            ) << "p = 1 - " << 1 - p;
        }
    }
    EXPECT_EQ(normalQuantile(0.5), 0.0);
}

// The uniform is open at both ends: the normal stays finite for every word
TEST(counterRandom, uniformOpenAndFiniteTails)
{
    EXPECT_GT(uniformOpen(0), 0.0);
    EXPECT_LT(uniformOpen(~std::uint64_t(0)), 1.0);
    EXPECT_EQ(uniformOpen(0), std::ldexp(1.0, -53));
    EXPECT_EQ(uniformOpen(~std::uint64_t(0)), 1 - std::ldexp(1.0, -53));
    const double most = standardNormal(~std::uint64_t(0));
    const double least = standardNormal(0);
    EXPECT_TRUE(std::isfinite(most) && std::isfinite(least));
    // the extreme words reach the quantile of 2^-53: 8.2 standard
    // deviations
    EXPECT_NEAR(least, lowerQuantile(std::ldexp(1.0, -53)), 1e-8);
    EXPECT_NEAR(most, -least, 1e-8);
}

// Consecutive counters of one key as the Brownian forces use them
// (counterWord(key, k), k = 0, 1, 2, ...; atom i's three numbers are 4 i,
// 4 i + 1, 4 i + 2): mean, variance, kurtosis, the probability beyond 3
// standard deviations and the correlations at lags 1, 2 and 4 within 5
// standard errors of the normal values; the sample's distribution within
// the Kolmogorov-Smirnov bound of 1 % false alarms (1.63/sqrt(n))
TEST(counterRandom, normalSampleFromHashedCounters)
{
    const std::size_t n = 2000000;
    std::vector<double> x(n);
    const std::uint64_t key = mix64(mix64(12345) ^ 678);
    const std::size_t lags[3] = {1, 2, 4};
    double sum = 0, sum2 = 0, sum4 = 0, sumLag[3] = {0, 0, 0};
    std::size_t beyond3 = 0;
    for (std::size_t k = 0; k < n; ++k)
    {
        x[k] = standardNormal(counterWord(key, k));
        for (int l = 0; l < 3; ++l)
            if (k >= lags[l]) sumLag[l] += x[k]*x[k - lags[l]];
        sum += x[k];
        sum2 += x[k]*x[k];
        sum4 += std::pow(x[k], 4);
        beyond3 += std::fabs(x[k]) > 3 ? 1 : 0;
    }
    const double mean = sum/n;
    const double variance = sum2/n - mean*mean;
    EXPECT_NEAR(mean, 0.0, 5/std::sqrt(double(n)));
    EXPECT_NEAR(variance, 1.0, 5*std::sqrt(2.0/n));
    EXPECT_NEAR(sum4/n, 3.0, 5*std::sqrt(96.0/n));     // var(x^4) = 105 - 9
    for (int l = 0; l < 3; ++l)
        EXPECT_NEAR(sumLag[l]/(n - lags[l]), 0.0, 5/std::sqrt(double(n - lags[l])))
            << "lag " << lags[l];
    const double pBeyond = 2*normalCdf(-3);
    EXPECT_NEAR
    (
        double(beyond3)/n, pBeyond, 5*std::sqrt(pBeyond*(1 - pBeyond)/n)
    );

    std::sort(x.begin(), x.end());
    double ks = 0;
    for (std::size_t k = 0; k < n; ++k)
    {
        const double F = normalCdf(x[k]);
        ks = std::max(ks, std::max(F - double(k)/n, double(k + 1)/n - F));
    }
    EXPECT_LT(ks, 1.63/std::sqrt(double(n)));
}


// The streams of two solves' keys are apart: the keys of consecutive steps
// (as the Brownian forces hash them) give uncorrelated numbers at the same
// and at shifted counters, and two keys j gamma apart (SplitMix64's
// states, which a sum key + n gamma would read shifted by j) do not repeat
// each other's words: the correlation within 5 standard errors of 0
TEST(counterRandom, streamsOfKeysApart)
{
    const std::uint64_t gamma = 0x9e3779b97f4a7c15ULL;
    const std::size_t n = 200000;
    const std::uint64_t key = mix64(mix64(4711) ^ 1000);
    const std::uint64_t nextStep = mix64(mix64(4711) ^ 1001);
    const std::uint64_t shiftedKey = key + 7*gamma;
    double same = 0, shifted = 0, apart = 0;
    for (std::size_t k = 0; k < n; ++k)
    {
        const double a = standardNormal(counterWord(key, k + 7));
        same += a*standardNormal(counterWord(nextStep, k + 7));
        shifted += a*standardNormal(counterWord(nextStep, k));
        apart += a*standardNormal(counterWord(shiftedKey, k));
    }
    const double bound = 5/std::sqrt(double(n));
    EXPECT_NEAR(same/n, 0.0, bound) << "the next step's key, same counter";
    EXPECT_NEAR(shifted/n, 0.0, bound) << "the next step's key, shifted counter";
    EXPECT_NEAR(apart/n, 0.0, bound) << "a key 7 gamma apart";
}
