#include "common.h"
namespace clothtear::bench {
int runStress(const BenchOptions&) { return 0; }
int runPeers(const BenchOptions&) { return 0; }
}
