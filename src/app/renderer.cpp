// Drawing the world with OpenGL 3.3 core.
//
// Section index:
//   [INIT]      programs, buffers, the sphere mesh, textures
//   [FRAME]     prepare() (reads the world, uploads) and submit(): clear, ground, the cloth's shadow,
//               cloth, torn threads, balls, overlays
//   [CLOTH]     render-mesh upload (topology only on revision change), lighting uniforms, the shadow,
//               the fringe of torn threads
//   [OVERLAYS]  structural / bend-shear springs as lines, weak and pinned particles as points
#include "renderer.h"

#include "gl_util.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace clothtear::app {

constexpr float kShadowReach = 1.f; // m: the contact shadow's darkness is 0.5 exp(-h / 0.25 m) (shadow.frag.glsl)

// ============================================================================================= [INIT]

std::string Renderer::init() {
    struct P {
        GLuint* target;
        const char *vs, *fs;
    } programs[] = {{&clothProgram_, "cloth.vert.glsl", "cloth.frag.glsl"},
                    {&clothInspectProgram_, "cloth.vert.glsl", "cloth_inspect.frag.glsl"},
                    {&litProgram_, "lit.vert.glsl", "lit.frag.glsl"},
                    {&groundProgram_, "ground.vert.glsl", "ground.frag.glsl"},
                    {&linesProgram_, "lines.vert.glsl", "lines.frag.glsl"},
                    {&fringeProgram_, "fringe.vert.glsl", "fringe.frag.glsl"},
                    {&shadowProgram_, "shadow.vert.glsl", "shadow.frag.glsl"}};
    for (const P& p : programs) {
        Result<GLuint> r = buildProgram(p.vs, p.fs);
        if (!r.ok()) return r.error;
        *p.target = r.value;
    }

    // Cloth: attribute 0..2 interleaved dynamic (position, normal, strain), 3 static uv.
    glGenVertexArrays(1, &clothVao_);
    glGenBuffers(1, &clothDynamicVbo_);
    glGenBuffers(1, &clothUvVbo_);
    glGenBuffers(1, &clothEbo_);
    glGenBuffers(1, &clothCoarseEbo_);
    glBindVertexArray(clothVao_);
    glBindBuffer(GL_ARRAY_BUFFER, clothDynamicVbo_);
    static_assert(kDynamicFloats == 3 + 3 + 1, "position, normal, strain");
    floatAttributes({3, 3, 1});
    glBindBuffer(GL_ARRAY_BUFFER, clothUvVbo_);
    floatAttributes({2}, 3);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, clothEbo_);
    glBindVertexArray(0);

    // Fringe: one interleaved buffer (fillFringeVertices), its own indices.
    glGenVertexArrays(1, &fringeVao_);
    glGenBuffers(1, &fringeVbo_);
    glGenBuffers(1, &fringeEbo_);
    glBindVertexArray(fringeVao_);
    glBindBuffer(GL_ARRAY_BUFFER, fringeVbo_);
    static_assert(kFringeFloats == 3 + 3 + 2 + 1 + 1, "position, normal, uv, thread, across");
    floatAttributes({3, 3, 2, 1, 1});
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, fringeEbo_);
    glBindVertexArray(0);

    // Overlays: particle positions straight from cloth.x (Vec3 is three packed floats).
    static_assert(sizeof(Vec3) == 3 * sizeof(float), "cloth.x must be packed floats for the overlay upload");
    glGenVertexArrays(1, &overlayVao_);
    glGenBuffers(1, &particleVbo_);
    glGenBuffers(1, &structuralEbo_);
    glGenBuffers(1, &bendEbo_);
    glGenBuffers(1, &pointsEbo_);
    glBindVertexArray(overlayVao_);
    glBindBuffer(GL_ARRAY_BUFFER, particleVbo_);
    floatAttributes({3});
    glBindVertexArray(0);

    // Ground quad.
    const float corners[] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    glGenVertexArrays(1, &groundVao_);
    glGenBuffers(1, &groundVbo_);
    glBindVertexArray(groundVao_);
    glBindBuffer(GL_ARRAY_BUFFER, groundVbo_);
    glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
    floatAttributes({2});
    glBindVertexArray(0);

    buildSphere();
    glGenTextures(1, &texture_);
    return {};
}

// A unit UV sphere; position doubles as normal.
void Renderer::buildSphere() {
    const int rings = 16, segments = 28;
    std::vector<float> v;
    std::vector<uint32_t> idx;
    for (int r = 0; r <= rings; ++r) {
        const float phi = float(M_PI) * float(r) / rings;
        for (int s = 0; s <= segments; ++s) {
            const float theta = 2.f * float(M_PI) * float(s) / segments;
            v.push_back(std::sin(phi) * std::cos(theta));
            v.push_back(std::cos(phi));
            v.push_back(std::sin(phi) * std::sin(theta));
        }
    }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
            idx.insert(idx.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    glGenVertexArrays(1, &sphereVao_);
    glGenBuffers(1, &sphereVbo_);
    glGenBuffers(1, &sphereEbo_);
    glBindVertexArray(sphereVao_);
    glBindBuffer(GL_ARRAY_BUFFER, sphereVbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(float)), v.data(), GL_STATIC_DRAW);
    floatAttributes({3});    // position
    floatAttributes({3}, 1); // and the same floats as the normal (a unit sphere)
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, sphereEbo_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(idx.size() * sizeof(uint32_t)), idx.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    sphereIndexCount_ = GLsizei(idx.size());
}

void Renderer::setTexture(const Image& image) {
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Upload bottom row first: GL puts the first row at v = 0, and the cloth has v = 1 at its top edge.
    std::vector<uint8_t> flipped(image.rgba.size());
    const size_t row = size_t(image.width) * 4;
    for (int y = 0; y < image.height; ++y)
        std::copy_n(&image.rgba[size_t(image.height - 1 - y) * row], row, &flipped[size_t(y) * row]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

void Renderer::shutdown() {
    for (GLuint p : {clothProgram_, clothInspectProgram_, litProgram_, groundProgram_, linesProgram_, fringeProgram_, shadowProgram_})
        if (p) glDeleteProgram(p);
    const GLuint buffers[] = {clothUvVbo_, clothDynamicVbo_, clothEbo_,  clothCoarseEbo_, particleVbo_, structuralEbo_,
                              bendEbo_,    pointsEbo_,       groundVbo_, sphereVbo_,      sphereEbo_,   fringeVbo_,
                              fringeEbo_};
    glDeleteBuffers(GLsizei(std::size(buffers)), buffers);
    const GLuint arrays[] = {clothVao_, overlayVao_, groundVao_, sphereVao_, fringeVao_};
    glDeleteVertexArrays(GLsizei(std::size(arrays)), arrays);
    if (texture_) glDeleteTextures(1, &texture_);
    *this = Renderer{};
}

// ============================================================================================ [FRAME]

void Renderer::prepare(const World& world, const RenderOptions& o, const View& view) {
    frame_.options = o;
    frame_.view = view;
    frame_.ground = world.settings.collision.ground;
    frame_.groundHeight = world.settings.collision.groundHeight;
    frame_.strainMax = world.settings.tear.enabled ? world.settings.tear.threshold : 0.5f;
    prepareCloth(world);
    prepareFringe(world);
    frame_.balls.clear();
    for (const Ball& b : world.balls) frame_.balls.emplace_back(b.x, b.radius);
    prepareOverlays(world);
}

void Renderer::submit(int fbWidth, int fbHeight) {
    const RenderOptions& o = frame_.options;
    glViewport(0, 0, fbWidth, fbHeight);
    glClearColor(o.sky[0], o.sky[1], o.sky[2], 1.f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE); // cloth is two-sided
    glDisable(GL_BLEND);
    if (frame_.ground) drawGround();
    if (frame_.shadow) drawShadow(); // over the ground, under the cloth
    drawCloth();
    drawFringe();
    drawBalls();
    drawOverlays();
    glBindVertexArray(0);
}

Renderer::DrawnState Renderer::drawnState(const World& world, bool strain) {
    // Positions move only in a step; a jump (undo, the timeline, a load) changes the step count or
    // the time, and the app calls invalidateTopology() after one anyway.
    return DrawnState{world.steps, world.cloth.topologyRevision, world.time, world.cloth.particleCount(), strain};
}

void Renderer::setLighting(GLuint program) {
    const RenderOptions& o = frame_.options;
    const View& view = frame_.view;
    Vec3 l(o.lightDir[0], o.lightDir[1], o.lightDir[2]);
    if (l.squaredNorm() < 1e-12f) l = Vec3::UnitY();
    setVec3(program, "uLightDir", Vec3(l.normalized()));
    setVec3(program, "uLightColor", o.lightColor);
    setVec3(program, "uAmbient", o.ambient);
    setVec3(program, "uCameraPos", view.camera.position());
    setFloat(program, "uSpecular", o.specular);
    setFloat(program, "uShininess", std::max(1.f, o.shininess));
    setMat4(program, "uViewProj", view.viewProjection.data());
}

void Renderer::drawGround() {
    const RenderOptions& o = frame_.options;
    const View& view = frame_.view;
    glUseProgram(groundProgram_);
    setLighting(groundProgram_);
    const float extent = std::max(60.f, view.camera.distance * 6.f);
    setFloat(groundProgram_, "uHeight", frame_.groundHeight);
    glUniform2f(uniform(groundProgram_, "uCenter"), std::round(view.camera.target.x()), std::round(view.camera.target.z()));
    setFloat(groundProgram_, "uExtent", extent);
    setFloat(groundProgram_, "uFadeDistance", extent * 0.9f);
    setVec3(groundProgram_, "uColor", o.ground);
    setVec3(groundProgram_, "uSky", o.sky);
    glBindVertexArray(groundVao_);
    // Drawn first, behind everything (colliders keep the cloth and balls above it): no depth traffic.
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
}

// ============================================================================================ [CLOTH]

void Renderer::prepareCloth(const World& world) {
    const Cloth& cloth = world.cloth;
    const RenderOptions& o = frame_.options;
    const View& view = frame_.view;
    frame_.cloth = !cloth.triangles.empty();
    frame_.shadow = false;
    frame_.clothIndices = 0;
    frame_.coarse = false;
    if (!frame_.cloth) return;
    glBindVertexArray(clothVao_);
    if (mesh_.stale(cloth)) {
        // Topology changed (a tear, a rebuild): new render vertices, uvs and indices.
        mesh_.rebuild(cloth);
        glBindBuffer(GL_ARRAY_BUFFER, clothUvVbo_);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh_.uv.size() * sizeof(float)), mesh_.uv.data(), GL_STATIC_DRAW);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, clothEbo_);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh_.indices.size() * sizeof(uint32_t)), mesh_.indices.data(),
                     GL_STATIC_DRAW);
        coarseRevision_ = ~uint64_t(0); // of the render vertices before
        ++topologyUploads_;
    }
    if (const DrawnState now = drawnState(world, o.strainColors); now != drawn_) {
        drawn_ = now;
        ++dynamicUploads_;
        computeParticleNormals(cloth, normals_);
        if (o.strainColors) computeParticleStrain(cloth, strain_);
        else strain_.clear();
        fillDynamicVertices(mesh_, cloth, normals_, strain_, dynamic_);
        glBindBuffer(GL_ARRAY_BUFFER, clothDynamicVbo_);
        // Orphan and refill: the driver need not wait for the previous frame's draw.
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(dynamic_.size() * sizeof(float)), dynamic_.data(), GL_STREAM_DRAW);
    }

    // One pass over the positions for two choices. From far, a grid cloth's intact blocks of 2 x 2
    // cells are drawn as two triangles (render_lod.h): when a cell (the mesh's mean rest length) at the
    // cloth's nearest point to the eye spans under kCoarseBelowPixels; the flat and strain views always
    // show every triangle. The coarse indices are made then, once per topology: a tearing cloth seen
    // near never pays for them. The contact shadow: when the cloth's lowest point is over 1 m above
    // the ground it would be invisible (darkness 0.01), and at 256 x 256 the pass cost llvmpipe about
    // twice the frame's raster work: skip it.
    frame_.inspect = o.flat || o.strainColors;
    const bool mayCoarsen = !frame_.inspect, mayShadow = frame_.ground && o.groundShadow;
    float lowest = std::numeric_limits<float>::infinity(), nearest2 = std::numeric_limits<float>::infinity();
    if (mayCoarsen || mayShadow) {
        const Vec3 eye = view.camera.position();
        for (const Vec3& x : cloth.x) {
            lowest = std::min(lowest, x.y());
            nearest2 = std::min(nearest2, (x - eye).squaredNorm());
        }
    }
    frame_.coarse = mayCoarsen && float(meanRestLength(cloth)) *
                                          pixelsPerMetre(std::sqrt(nearest2), view.camera.fovY, view.height) <
                                      kCoarseBelowPixels;
    if (frame_.coarse && coarseRevision_ != mesh_.revision) {
        coarse_ = coarseGridIndices(cloth, mesh_);
        coarseRevision_ = mesh_.revision;
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, clothCoarseEbo_); // binds it to clothVao_ until drawCloth
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(coarse_.size() * sizeof(uint32_t)), coarse_.data(),
                     GL_STATIC_DRAW);
    }
    frame_.coarse = frame_.coarse && !coarse_.empty(); // none intact: an irregular or OBJ mesh
    frame_.clothIndices = frame_.coarse ? coarse_.size() : mesh_.indices.size();
    frame_.shadow = mayShadow && lowest - frame_.groundHeight < kShadowReach;
}

// The cloth's element buffer for this frame, fine or coarse, bound to clothVao_.
void Renderer::bindClothIndices() {
    glBindVertexArray(clothVao_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, frame_.coarse ? clothCoarseEbo_ : clothEbo_);
}

void Renderer::drawCloth() {
    if (!frame_.cloth) return;
    const RenderOptions& o = frame_.options;
    bindClothIndices();
    // The default view interpolates only what it shades with (cloth.*.glsl): llvmpipe sets up every
    // interpolated float of every triangle. The flat and strain views need the world position and the
    // strain as well (cloth_inspect.frag.glsl; the vertex shader is the same, the linker drops what
    // cloth.frag.glsl does not read).
    const GLuint program = frame_.inspect ? clothInspectProgram_ : clothProgram_;
    glUseProgram(program);
    setLighting(program);
    setInt(program, "uUseTexture", o.texture ? 1 : 0);
    if (frame_.inspect) {
        setInt(program, "uFlat", o.flat ? 1 : 0);
        setInt(program, "uStrainColors", o.strainColors ? 1 : 0);
        setFloat(program, "uStrainMax", frame_.strainMax);
    }
    setVec3(program, "uFrontTint", o.frontTint);
    setVec3(program, "uBackColor", o.backColor);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    setInt(program, "uTexture", 0);
    // Push the cloth slightly back so overlay lines on it win the depth test.
    const bool overlays = o.structuralSprings || o.bendSprings;
    if (overlays) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.f, 1.f);
    }
    glDrawElements(GL_TRIANGLES, GLsizei(frame_.clothIndices), GL_UNSIGNED_INT, nullptr);
    glDisable(GL_POLYGON_OFFSET_FILL);
}

// The cloth's triangles once more, pushed down onto the ground (shaders/shadow.*.glsl):
// over the ground just drawn, before the cloth, blended with GL_MIN so that overlapping layers do not
// darken twice. No depth: the ground wrote none.
void Renderer::drawShadow() {
    const RenderOptions& o = frame_.options;
    bindClothIndices();
    glUseProgram(shadowProgram_);
    setLighting(shadowProgram_);
    const float extent = std::max(60.f, frame_.view.camera.distance * 6.f);
    setFloat(shadowProgram_, "uHeight", frame_.groundHeight);
    setFloat(shadowProgram_, "uFadeDistance", extent * 0.9f);
    setVec3(shadowProgram_, "uColor", o.ground);
    setVec3(shadowProgram_, "uSky", o.sky);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_MIN);
    glDrawElements(GL_TRIANGLES, GLsizei(frame_.clothIndices), GL_UNSIGNED_INT, nullptr);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
}

// Loose threads along the torn edges: the strips rebuilt with the topology, moved every frame with
// the cloth (the normals prepareCloth computed), one draw call.
void Renderer::prepareFringe(const World& world) {
    const Cloth& cloth = world.cloth;
    frame_.fringeIndices = 0;
    if (!frame_.options.fringe || frame_.options.strainColors || cloth.triangles.empty()) return;
    glBindVertexArray(fringeVao_);
    if (fringe_.stale(cloth)) {
        fringe_.rebuild(cloth, float(kWovenThreads));
        fringeIndices(fringe_.edges.size(), fringeIndices_);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, fringeEbo_);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(fringeIndices_.size() * sizeof(uint32_t)),
                     fringeIndices_.data(), GL_STATIC_DRAW);
    }
    if (fringe_.edges.empty()) return;
    fillFringeVertices(fringe_, cloth, normals_, fringeVertices_);
    glBindBuffer(GL_ARRAY_BUFFER, fringeVbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(fringeVertices_.size() * sizeof(float)), fringeVertices_.data(),
                 GL_STREAM_DRAW);
    frame_.fringeIndices = fringeIndices_.size();
}

void Renderer::drawFringe() {
    if (frame_.fringeIndices == 0) return;
    const RenderOptions& o = frame_.options;
    glBindVertexArray(fringeVao_);
    glUseProgram(fringeProgram_);
    setLighting(fringeProgram_);
    setInt(fringeProgram_, "uUseTexture", o.texture ? 1 : 0);
    setVec3(fringeProgram_, "uFrontTint", o.frontTint);
    setVec3(fringeProgram_, "uBackColor", o.backColor);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    setInt(fringeProgram_, "uTexture", 0);
    glDrawElements(GL_TRIANGLES, GLsizei(frame_.fringeIndices), GL_UNSIGNED_INT, nullptr);
}

void Renderer::drawBalls() {
    if (frame_.balls.empty()) return;
    glUseProgram(litProgram_);
    setLighting(litProgram_);
    setVec3(litProgram_, "uColor", frame_.options.ballColor);
    glBindVertexArray(sphereVao_);
    for (const auto& [centre, radius] : frame_.balls) {
        Eigen::Affine3f model = Eigen::Translation3f(centre) * Eigen::Scaling(radius);
        setMat4(litProgram_, "uModel", model.matrix().data());
        glDrawElements(GL_TRIANGLES, sphereIndexCount_, GL_UNSIGNED_INT, nullptr);
    }
}

// ========================================================================================= [OVERLAYS]

void Renderer::prepareOverlays(const World& world) {
    const Cloth& cloth = world.cloth;
    const RenderOptions& o = frame_.options;
    frame_.overlays = (o.structuralSprings || o.bendSprings || o.weakPoints || o.pinnedParticles) && cloth.particleCount() > 0;
    frame_.weakPoints = frame_.pinnedPoints = 0;
    if (!frame_.overlays) return;
    glBindVertexArray(overlayVao_);
    glBindBuffer(GL_ARRAY_BUFFER, particleVbo_);
    if (const DrawnState now = drawnState(world, false); now != overlayDrawn_) {
        overlayDrawn_ = now;
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(cloth.particleCount() * sizeof(Vec3)), cloth.x.data(), GL_STREAM_DRAW);
    }
    if (overlayRevision_ != cloth.topologyRevision || overlayParticles_ != cloth.particleCount() ||
        GLsizei(cloth.springs.size() * 2) != structuralCount_ || GLsizei(cloth.bends.size() * 2) != bendCount_) {
        auto upload = [&](GLuint ebo, const std::vector<Spring>& springs) {
            pointScratch_.clear();
            for (const Spring& s : springs) pointScratch_.insert(pointScratch_.end(), {s.a, s.b});
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(pointScratch_.size() * sizeof(uint32_t)),
                         pointScratch_.data(), GL_STATIC_DRAW);
            return GLsizei(pointScratch_.size());
        };
        structuralCount_ = upload(structuralEbo_, cloth.springs);
        bendCount_ = upload(bendEbo_, cloth.bends);
        overlayRevision_ = cloth.topologyRevision;
        overlayParticles_ = cloth.particleCount();
    }
    // Points: pins change without a topology revision, so these lists are rebuilt each frame, the
    // weak points first, then the pinned ones, in one buffer.
    pointScratch_.clear();
    auto list = [&](bool wanted, uint8_t flag) {
        const size_t before = pointScratch_.size();
        if (wanted)
            for (Index p = 0; p < cloth.particleCount(); ++p)
                if (cloth.flags[p] & flag) pointScratch_.push_back(p);
        return GLsizei(pointScratch_.size() - before);
    };
    frame_.weakPoints = list(o.weakPoints, kWeak);
    frame_.pinnedPoints = list(o.pinnedParticles, kPinned);
    if (!pointScratch_.empty()) {
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, pointsEbo_);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(pointScratch_.size() * sizeof(uint32_t)), pointScratch_.data(),
                     GL_STREAM_DRAW);
    }
}

void Renderer::drawOverlays() {
    if (!frame_.overlays) return;
    const RenderOptions& o = frame_.options;
    glBindVertexArray(overlayVao_);
    glUseProgram(linesProgram_);
    setMat4(linesProgram_, "uViewProj", frame_.view.viewProjection.data());
    setFloat(linesProgram_, "uPointSize", 1.f);
    const GLint color = uniform(linesProgram_, "uColor");
    if (o.bendSprings) {
        glUniform4f(color, 0.15f, 0.45f, 0.95f, 1.f);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bendEbo_);
        glDrawElements(GL_LINES, bendCount_, GL_UNSIGNED_INT, nullptr);
    }
    if (o.structuralSprings) {
        glUniform4f(color, 0.08f, 0.08f, 0.1f, 1.f);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, structuralEbo_);
        glDrawElements(GL_LINES, structuralCount_, GL_UNSIGNED_INT, nullptr);
    }
    glEnable(GL_PROGRAM_POINT_SIZE);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, pointsEbo_);
    auto points = [&](GLsizei first, GLsizei count, float size, float r, float g, float b) {
        if (count == 0) return;
        setFloat(linesProgram_, "uPointSize", size);
        glUniform4f(color, r, g, b, 1.f);
        glDrawElements(GL_POINTS, count, GL_UNSIGNED_INT, reinterpret_cast<const void*>(size_t(first) * sizeof(uint32_t)));
    };
    points(0, frame_.weakPoints, 5.f, 1.f, 0.55f, 0.05f);
    points(frame_.weakPoints, frame_.pinnedPoints, 6.f, 0.55f, 0.05f, 0.1f);
    glDisable(GL_PROGRAM_POINT_SIZE);
}

} // namespace clothtear::app
