#include "common.h"
namespace clothtear::bench {
int runStability(const BenchOptions&) { return 0; }
int runStatic(const BenchOptions&) { return 0; }
int runSkipping(const BenchOptions&) { return 0; }
int runStress(const BenchOptions&) { return 0; }
int runPeers(const BenchOptions&) { return 0; }
}
