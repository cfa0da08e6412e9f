// The soak run (soak.h): one world, a random person at the controls, checks and a line per period.
#include "soak.h"

#include "clothtear/random.h"
#include "clothtear/scenes.h"
#include "clothtear/tear.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <sstream>

namespace clothtear {

double residentMiB() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmRSS:", 0) == 0)
            return std::strtod(line.c_str() + 6, nullptr) / 1024.0; // kB
    return 0;
}

namespace {

// A grab in progress: particles driven along a direction until `release` (simulated seconds).
struct Grab {
    size_t driver;
    double release;
};

class Soak {
  public:
    Soak(const SoakOptions& o, std::ostream& log) : o_(o), log_(log), rng_(Rng(o.seed).next()) {}

    SoakResult run() {
        using Clock = std::chrono::steady_clock;
        const auto start = Clock::now();
        auto wall = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
        rebuild();
        r_.rssStartMiB = r_.rssMaxMiB = residentMiB();
        line(0.0);
        double nextReport = o_.reportSeconds;
        while (r_.ok()) {
            if (o_.maxFrames >= 0 ? r_.frames >= o_.maxFrames : wall() >= 60.0 * o_.minutes)
                break;
            interact();
            w_.step();
            ++r_.frames;
            if (!w_.finite)
                r_.failure = "non-finite value " + w_.nonFiniteWhere;
            if (r_.ok() && w_.cloth.particleCount() > 4 * particles0_) { // shredded: a fresh cloth
                check();
                rebuild();
            }
            if (wall() >= nextReport) {
                check();
                line(wall());
                nextReport += o_.reportSeconds;
            }
        }
        check();
        r_.tears += w_.tearLog.total();
        done_ = true;
        r_.rssEndMiB = residentMiB();
        r_.rssMaxMiB = std::max(r_.rssMaxMiB, r_.rssEndMiB);
        line(wall());
        return r_;
    }

  private:
    void rebuild() {
        if (r_.frames > 0) {
            r_.tears += w_.tearLog.total();
            ++r_.rebuilds;
        }
        const std::string res = std::to_string(o_.resolution);
        const std::vector<std::string> sets = {"cloth.resolution_x=" + res, "cloth.resolution_y=" + res,
                                               "check.finite=1"};
        if (std::string err = loadScene(w_, "curtain", sets); !err.empty())
            r_.failure = "cannot load: " + err;
        particles0_ = w_.cloth.particleCount();
        area0_ = w_.cloth.totalRestArea();
        uv0_ = w_.cloth.totalUvArea();
        grabs_.clear();
    }

    // What a person might do this frame, at a few actions per simulated second, with the strengths
    // of the app's tools around their defaults (ball 3 m/s and 2 kg, wind 6 m/s).
    void interact() {
        const double dt = w_.settings.time.frameDt;
        Cloth& c = w_.cloth;
        // Let go of grabs that are over: their particles fall free again.
        for (size_t i = grabs_.size(); i-- > 0;)
            if (w_.time >= grabs_[i].release) {
                for (Index p : w_.drivers[grabs_[i].driver].particles)
                    c.setPinned(p, false);
                w_.drivers[grabs_[i].driver].particles.clear();
                grabs_.erase(grabs_.begin() + long(i));
            }
        if (grabs_.empty())
            w_.drivers.clear();
        const Index any = rng_.below(uint32_t(c.particleCount()));
        if (rng_.uniform() < 0.8 * dt && grabs_.size() < 2 && !c.pinned(any)) {
            // Grab a patch and drag it: in the plane and out of it, slowly or hard enough to tear.
            Driver d;
            const float radius = float(rng_.uniform(0.02, 0.12));
            for (Index p = 0; p < c.particleCount(); ++p)
                if (!c.pinned(p) && (c.x[p] - c.x[any]).norm() < radius)
                    d.particles.push_back(p);
            for (Index p : d.particles)
                c.setPinned(p, true);
            const Vec3 dir =
                Vec3(float(rng_.uniform(-1, 1)), float(rng_.uniform(-1, 0.3)), float(rng_.uniform(-1, 1)));
            d.velocity = dir.normalized() * float(rng_.uniform(0.2, 1.5));
            grabs_.push_back({w_.drivers.size(), w_.time + rng_.uniform(0.2, 1.5)});
            w_.drivers.push_back(std::move(d));
            ++r_.grabs;
        }
        if (rng_.uniform() < 1.0 * dt) {
            const Vec3 dir(float(rng_.uniform(-1, 1)), float(rng_.uniform(-1, 1)),
                           float(rng_.uniform(-1, 1)));
            w_.applyImpulse(c.x[any], float(rng_.uniform(0.1, 0.5)), dir, float(rng_.uniform(0.3, 2.0)));
            ++r_.impulses;
        }
        if (rng_.uniform() < 0.3 * dt && w_.balls.size() < 4) {
            Ball b;
            b.radius = float(rng_.uniform(0.05, 0.5));
            b.mass = float(rng_.uniform(0.5, 5.0));
            b.x = Vec3(float(rng_.uniform(-1, 1)), float(rng_.uniform(-1, 1)), 2.f);
            b.v = (c.x[any] - b.x).normalized() * float(rng_.uniform(2.0, 6.0));
            w_.balls.push_back(b);
            ++r_.balls;
        }
        // Balls that fell past the ground or flew away leave.
        std::erase_if(w_.balls, [&](const Ball& b) {
            return b.x.norm() > 50.f || b.x.y() < w_.settings.collision.groundHeight - 1.f;
        });
        if (rng_.uniform() < 0.1 * dt) {
            WindSettings& wind = w_.settings.wind;
            wind.enabled = !wind.enabled;
            wind.dirX = float(rng_.uniform(-1, 1));
            wind.dirZ = float(rng_.uniform(-1, 1));
            wind.speed = float(rng_.uniform(2, 8));
        }
    }

    void check() {
        if (!r_.ok())
            return;
        if (std::string err = validateCloth(w_.cloth, area0_, uv0_); !err.empty())
            r_.failure = "invariant broken at frame " + std::to_string(r_.frames) + ": " + err;
    }

    void line(double wallSeconds) {
        const double rss = residentMiB();
        r_.rssMaxMiB = std::max(r_.rssMaxMiB, rss);
        const auto& t = w_.tearLog.counts;
        char buf[512];
        std::snprintf(buf, sizeof buf,
                      "soak %7.0f s  frames %9ld  steps/s %6.0f  particles %6zu  triangles %6zu  tears %8llu "
                      "(now %llu/%llu/%llu)  rebuilds %3d  grabs %6llu  balls %5llu  RSS %7.1f MiB  finite "
                      "%s  valid %s",
                      wallSeconds, r_.frames, wallSeconds > 0 ? double(r_.frames) / wallSeconds : 0.0,
                      w_.cloth.particleCount(), w_.cloth.triangles.size(),
                      (unsigned long long)(r_.tears + (done_ ? 0 : w_.tearLog.total())),
                      (unsigned long long)t[0], (unsigned long long)t[1], (unsigned long long)t[2],
                      r_.rebuilds, (unsigned long long)r_.grabs, (unsigned long long)r_.balls, rss,
                      w_.finite ? "yes" : "NO", r_.ok() ? "yes" : "NO");
        log_ << buf << std::endl;
        if (!r_.ok())
            log_ << "soak: FAILED: " << r_.failure << std::endl;
    }

    const SoakOptions& o_;
    std::ostream& log_;
    Rng rng_;
    World w_;
    SoakResult r_;
    std::vector<Grab> grabs_;
    size_t particles0_ = 0;
    double area0_ = 0, uv0_ = 0;
    bool done_ = false; // the last line: r_.tears already holds this cloth's tears
};

} // namespace

SoakResult runSoak(const SoakOptions& options, std::ostream& log) {
    Soak soak(options, log);
    SoakResult r = soak.run();
    return r;
}

} // namespace clothtear
