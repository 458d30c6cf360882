// Time per node of the world-edge search (spatialHash: hash the world
// positions, then the pairs of different bodies within the radius), from
// 1e3 to 1e5 nodes at a fixed density, on two scenes:
//   contact: two bodies (the halves of a random cloud of 8 points per unit
//            volume, radius 1: about 33 neighbours per node, ~4 world
//            edges per node near the interface)
//   apart:   the same two bodies 1e4 radii apart (the extent of the cloud
//            no longer follows its size: what uniform bins over the
//            bounding box would pay for)
// Each time is the least of 5 repetitions, each long enough (>= 0.1 s).
// Usage: worldEdgesBenchmark [nMax]       (default 100000)

#include "spatialHash.H"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

using namespace Foam;

namespace
{

double seconds(const std::chrono::steady_clock::time_point& t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The least over 5 repetitions of the time of one search (hash and
// pairs), its hashing part, and its pairs
double timeSearch
(
    const pointField& x,
    const labelList& body,
    double& hashTime,
    label& nPairs
)
{
    double best = 1e30;
    hashTime = 1e30;
    // As a graph rebuilt every model step uses it: one hash and one pair
    // list, rebuilt (their memory reused)
    spatialHash hash(1.0);
    DynamicList<label> a, b;
    for (int rep = 0; rep < 5; ++rep)
    {
        label nRuns = 0;
        double t = 0, th = 0;
        do
        {
            const auto t0 = std::chrono::steady_clock::now();
            hash.build(x);
            th += seconds(t0);
            a.clear();
            b.clear();
            hash.pairs(body, a, b);
            nPairs = a.size();
            ++nRuns;
            t += seconds(t0);
        } while (t < 0.1);
        best = std::min(best, t/nRuns);
        hashTime = std::min(hashTime, th/nRuns);
    }
    return best;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    const label nMax = argc > 1 ? std::atol(argv[1]) : 100000;
    const double density = 8;
    std::printf("# scene    nodes  pairs  ns_per_node  ratio_to_1e3  hash_ns_per_node\n");
    for (const char* scene : {"contact", "apart"})
    {
        double first = 0;
        for (label n = 1000; n <= nMax; n = label(std::lround(n*std::sqrt(10.0))))
        {
            const double side = std::cbrt(n/density);
            std::mt19937 gen(7);
            std::uniform_real_distribution<double> u(0, side);
            pointField x(n);
            labelList body(n);
            for (label i = 0; i < n; ++i)
            {
                x[i] = point(u(gen), u(gen), u(gen));
                body[i] = x[i].x() < 0.5*side ? 0 : 1;
                if (scene[0] == 'a' && body[i] == 1) x[i].x() += 1e4;
            }
            label nPairs = 0;
            double th = 0;
            const double t = timeSearch(x, body, th, nPairs);
            const double perNode = 1e9*t/n;
            if (first == 0) first = perNode;
            std::printf
            (
                "%-8s %7d %6d %12.1f %12.3f %12.1f\n",
                scene, int(n), int(nPairs), perNode, perNode/first, 1e9*th/n
            );
        }
    }
    return 0;
}
