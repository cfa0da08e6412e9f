// Bullet soft-body cloth for the peers mode (peers.h). Compiled only when CMake finds Bullet
// (Debian package libbullet-dev); see bench/CMakeLists.txt.
#include "../peers.h"

#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

namespace clothtear::bench {

PeerResult runBulletCloth(int n, double settleSeconds, int measureSubsteps, int repetitions,
                          int positionIterations, int substepsPerFrame) {
    PeerResult r;
    r.available = true;
    r.note = "Bullet " + std::to_string(BT_BULLET_VERSION);
    auto config = std::make_unique<btSoftBodyRigidBodyCollisionConfiguration>();
    auto dispatcher = std::make_unique<btCollisionDispatcher>(config.get());
    auto broadphase = std::make_unique<btDbvtBroadphase>();
    auto solver = std::make_unique<btSequentialImpulseConstraintSolver>();
    auto world = std::make_unique<btSoftRigidDynamicsWorld>(dispatcher.get(), broadphase.get(), solver.get(),
                                                            config.get());
    world->setGravity(btVector3(0, -9.81f, 0));
    btSoftBodyWorldInfo& info = world->getWorldInfo();
    info.m_gravity = btVector3(0, -9.81f, 0);
    info.m_sparsesdf.Initialize();
    // 2 m x 2 m in the x-y plane, top edge at y = 1 (as our curtain).
    btSoftBody* cloth =
        btSoftBodyHelpers::CreatePatch(info, btVector3(-1, 1, 0), btVector3(1, 1, 0), btVector3(-1, -1, 0),
                                       btVector3(1, -1, 0), n, n, 0, true);
    cloth->setTotalMass(0.8f); // 0.2 kg/m^2 over 4 m^2, as ours
    for (int i = 0; i < cloth->m_nodes.size(); ++i)
        if (cloth->m_nodes[i].m_x.y() > 1 - 1e-4f)
            cloth->setMass(i, 0); // top row fixed
    if (positionIterations > 0)
        cloth->m_cfg.piterations = positionIterations;
    r.positionIterations = cloth->m_cfg.piterations;
    cloth->randomizeConstraints();
    world->addSoftBody(cloth);
    const btScalar dt = 1.f / (60.f * float(substepsPerFrame));
    for (int i = 0; i < int(settleSeconds / dt); ++i)
        world->stepSimulation(dt, 0);
    double best = 1e300;
    for (int rep = 0; rep < repetitions; ++rep) {
        const auto t0 = std::chrono::steady_clock::now();
        for (int i = 0; i < measureSubsteps; ++i)
            world->stepSimulation(dt, 0);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        best = std::min(best, 1000.0 * s / measureSubsteps);
    }
    r.msPerSubstep = best;
    double sum = 0, worst = -1e30;
    for (int i = 0; i < cloth->m_links.size(); ++i) {
        const btSoftBody::Link& l = cloth->m_links[i];
        const double s = double((l.m_n[1]->m_x - l.m_n[0]->m_x).length() / l.m_rl) - 1.0;
        sum += s;
        worst = std::max(worst, s);
    }
    r.links = size_t(cloth->m_links.size());
    r.meanStretch = r.links ? sum / double(r.links) : 0;
    r.worstStretch = worst;
    world->removeSoftBody(cloth);
    delete cloth;
    return r;
}

} // namespace clothtear::bench
