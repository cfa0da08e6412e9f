// Mode `stress`: a long randomized run of interactions on a tearing cloth, seeded and reproducible
// (the script depends on the seed and the frame number only; results also on the thread count),
// checking every tearing invariant and that memory grows no more than the topology it created.
//
// Cloth: the tearing scenes' default (6 m x 6 m, 10 kg balls, thresholds of tearClothConfig) at
// --stress-resolution (128) particles per side, top edge pinned, ground at -5 m. Every 0.3-1.5 s
// one event: a ball thrown at a random point (radius 0.1-0.8 m, 2-15 m/s, 0.5-20 kg), a drag (a
// random particle pinned and driven at 0.5-4 m/s for 0.3-2 s, then released), an impulse (1-6 m/s
// on a 0.1-0.6 m patch), or wind switched on or off; balls below the ground are removed.
// Every second: validateCloth (every invariant), finiteness, particle/spring/triangle counts, the
// bytes the cloth's arrays hold, and the process's resident memory.
#include "clothtear/random.h"
#include "clothtear/tear.h"
#include "common.h"
#include "report.h"

#include <cstdio>
#include <vector>

namespace clothtear::bench {
namespace {

// Bytes held by the cloth's arrays: allocated (capacity) or in use (size). Vectors grow by
// doubling, so the allocated bytes may be up to twice the used ones: the bound to check is that
// used bytes per particle/spring/triangle stay the same, and allocated stays within 2x of used.
template <class T> size_t bytesOf(const std::vector<T>& v, bool capacity) {
    return (capacity ? v.capacity() : v.size()) * sizeof(T);
}

size_t clothBytes(const Cloth& c, bool capacity = true) {
    size_t b = bytesOf(c.x, capacity) + bytesOf(c.v, capacity) +
               bytesOf(c.invMass, capacity) + bytesOf(c.areaShare, capacity) + bytesOf(c.rest, capacity) +
               bytesOf(c.flags, capacity) + bytesOf(c.particleTris, capacity) + bytesOf(c.springs, capacity) +
               bytesOf(c.springTopo, capacity) + bytesOf(c.bends, capacity) + bytesOf(c.bendEdge, capacity) +
               bytesOf(c.triangles, capacity);
    for (const auto& t : c.particleTris)
        b += bytesOf(t, capacity);
    return b;
}

} // namespace

int runStress(const BenchOptions& opt) {
    setThreads(opt.threads);
    const std::string r = std::to_string(opt.stressResolution);
    World w =
        loadOrThrow("pull", {"cloth.resolution_x=" + r, "cloth.resolution_y=" + r, "collision.ground=true"});
    w.drivers.clear(); // the pull scene's driver: the script does the pulling
    for (Index p = 0; p < w.cloth.particleCount(); ++p)
        w.cloth.setPinned(p, false);
    w.pinByMode(PinMode::TopEdge);
    Rng rng(opt.seed);
    const double seconds = opt.quick ? std::min(opt.stressSeconds, 10.0) : opt.stressSeconds;
    const int frames = int(seconds * 60);
    Csv csv(opt.out + "/stress.csv",
            {"t", "particles", "springs", "bends", "triangles", "tears", "balls", "cloth_bytes",
             "cloth_bytes_used", "rss_bytes", "max_strain", "valid", "wall_s"});
    std::printf("\n== stress (%dx%d tearing cloth, seed %llu, %.0f simulated s, %d thread(s))\n",
                opt.stressResolution, opt.stressResolution, (unsigned long long)opt.seed, seconds,
                opt.threads);
    const size_t p0 = w.cloth.particleCount(), s0 = w.cloth.springs.size(), t0n = w.cloth.triangles.size();
    const size_t bytes0 = clothBytes(w.cloth), rss0 = residentBytes(), usedStart = clothBytes(w.cloth, false);
    int events[4] = {0, 0, 0, 0};
    double nextEvent = 0.5, dragEnd = -1;
    std::string invalid;
    const auto start = std::chrono::steady_clock::now();
    size_t rssPeak = rss0, bytesPeak = bytes0;
    for (int f = 0; f < frames && invalid.empty(); ++f) {
        if (w.time >= dragEnd && !w.drivers.empty()) {
            for (const Driver& d : w.drivers)
                for (Index p : d.particles)
                    w.cloth.setPinned(p, false);
            w.drivers.clear();
        }
        if (w.time >= nextEvent) {
            nextEvent = w.time + rng.uniform(0.3, 1.5);
            const Index target = Index(rng.below(uint32_t(w.cloth.particleCount())));
            const Vec3 aim = w.cloth.x[target];
            const int kind = int(rng.below(4));
            ++events[kind];
            if (kind == 0) {
                Ball b;
                b.radius = float(rng.uniform(0.1, 0.8));
                b.mass = float(rng.uniform(0.5, 20));
                const Vec3 from =
                    aim + Vec3(float(rng.uniform(-1, 1)), float(rng.uniform(-0.5, 1)), 2.f + b.radius);
                b.x = from;
                b.v = (aim - from).normalized() * float(rng.uniform(2, 15));
                w.balls.push_back(b);
            } else if (kind == 1 && w.drivers.empty() && !w.cloth.pinned(target)) {
                w.cloth.setPinned(target, true);
                const Vec3 dir(float(rng.uniform(-1, 1)), float(rng.uniform(-1, 1)),
                               float(rng.uniform(-1, 1)));
                w.drivers.push_back(Driver{{target}, dir.normalized() * float(rng.uniform(0.5, 4))});
                dragEnd = w.time + rng.uniform(0.3, 2);
            } else if (kind == 2) {
                const Vec3 dir(float(rng.uniform(-1, 1)), float(rng.uniform(-1, 1)),
                               float(rng.uniform(-1, 1)));
                w.applyImpulse(aim, float(rng.uniform(0.1, 0.6)), dir, float(rng.uniform(1, 6)));
            } else {
                w.settings.wind.enabled = !w.settings.wind.enabled;
                w.settings.wind.speed = float(rng.uniform(2, 15));
                w.settings.wind.dirX = float(rng.uniform(-1, 1));
                w.settings.wind.dirZ = float(rng.uniform(-1, 1));
            }
        }
        std::erase_if(w.balls, [&](const Ball& b) {
            return b.x.y() < w.settings.collision.groundHeight + b.radius + 0.01f &&
                   b.v.squaredNorm() < 0.01f;
        });
        w.step();
        if (!w.finite)
            invalid = "non-finite: " + w.nonFiniteWhere;
        if (f % 60 == 59 || f == frames - 1 || !invalid.empty()) {
            if (invalid.empty())
                invalid = validateCloth(w.cloth);
            if (invalid.empty())
                invalid = w.tearLog.validationError;
            const size_t bytes = clothBytes(w.cloth), rss = residentBytes();
            rssPeak = std::max(rssPeak, rss);
            bytesPeak = std::max(bytesPeak, bytes);
            csv.row(w.time, w.cloth.particleCount(), w.cloth.springs.size(), w.cloth.bends.size(),
                    w.cloth.triangles.size(), w.tearLog.total(), w.balls.size(), bytes,
                    clothBytes(w.cloth, false), rss, w.maxStrain, int(invalid.empty()), secondsSince(start));
            if (f % 600 == 599)
                std::printf(
                    "  t %6.1f s: %zu particles, %zu triangles, %llu tears, cloth %.1f MB, resident %.1f MB, "
                    "%.0f s wall\n",
                    w.time, w.cloth.particleCount(), w.cloth.triangles.size(),
                    (unsigned long long)w.tearLog.total(), bytes / 1e6, rss / 1e6, secondsSince(start));
        }
    }
    const size_t p1 = w.cloth.particleCount(), s1 = w.cloth.springs.size(), t1 = w.cloth.triangles.size();
    const size_t bytes1 = clothBytes(w.cloth), rss1 = residentBytes();
    const size_t used0 = usedStart, used1 = clothBytes(w.cloth, false);
    std::printf("  events: %d balls, %d drags, %d impulses, %d wind switches; %llu tears\n", events[0],
                events[1], events[2], events[3], (unsigned long long)w.tearLog.total());
    std::printf(
        "  topology: particles %zu -> %zu (+%.1f%%), springs %zu -> %zu, triangles %zu -> %zu (+%.1f%%)\n",
        p0, p1, 100.0 * (double(p1) / p0 - 1), s0, s1, t0n, t1, 100.0 * (double(t1) / t0n - 1));
    std::printf(
        "  cloth arrays: %.2f -> %.2f MB (+%.1f%%, peak %.2f); resident: %.1f -> %.1f MB (peak %.1f); "
        "bytes per particle %.0f -> %.0f\n",
        bytes0 / 1e6, bytes1 / 1e6, 100.0 * (double(bytes1) / bytes0 - 1), bytesPeak / 1e6, rss0 / 1e6,
        rss1 / 1e6, rssPeak / 1e6, double(bytes0) / p0, double(bytes1) / p1);
    std::printf("  cloth arrays in use: %.2f -> %.2f MB; per particle %.1f -> %.1f B, per (particle + spring "
                "+ triangle) "
                "%.1f -> %.1f B\n",
                used0 / 1e6, used1 / 1e6, double(used0) / p0, double(used1) / p1,
                double(used0) / double(p0 + s0 + t0n), double(used1) / double(p1 + s1 + t1));
    std::printf("  invariants: %s; %.0f s wall for %.0f simulated s\n",
                invalid.empty() ? "held at every check" : invalid.c_str(), secondsSince(start), w.time);
    return invalid.empty() ? 0 : 1;
}

} // namespace clothtear::bench
