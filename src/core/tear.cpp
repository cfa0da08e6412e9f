// Tearing: placeholder until the tearing issue lands (candidates are found by the strain scan).
#include "clothtear/tear.h"

namespace clothtear {

const char* tearModeName(TearMode m) {
    static const char* names[] = {"basic", "weak_point", "one_point"};
    return names[int(m)];
}

int tearSprings(Cloth&, std::vector<TearCandidate>&, const TearContext&) { return 0; }
bool forceTear(Cloth&, Index, const TearContext&) { return false; }

} // namespace clothtear
