// The renderer: owns every GPU object and draws the world (sky, ground and the cloth's shadow on it,
// cloth, the loose threads of its torn edges, balls, debug overlays).
// It reads the core's arrays; the core knows nothing of it. Uploads follow what changed: positions and
// normals when the world stepped (or jumped), index buffers only when cloth.topologyRevision moved.
#pragma once
#include "app_state.h"
#include "fabric_texture.h"
#include "render_lod.h"
#include "render_mesh.h"

#include <GL/glew.h>
#include <string>
#include <utility>
#include <vector>

namespace clothtear::app {

class Renderer {
public:
    // Compiles the shaders and creates the buffers. Returns "" or what failed.
    std::string init();
    void shutdown();
    // Replaces the cloth texture (mipmapped, repeat).
    void setTexture(const Image& image);
    // A frame in two halves, so that the world may be stepped between them (the app's pipeline,
    // src/app/README.md "The frame"): prepare() is the only one that reads the world: it uploads what
    // changed (positions and normals, the topology's indices, the fringe, the overlays' lists; GL
    // copies them) and notes what the frame draws. submit() issues the GL draws of that frame into the
    // current framebuffer of fbWidth x fbHeight pixels and reads nothing of the world.
    void prepare(const World& world, const RenderOptions& options, const View& view);
    void submit(int fbWidth, int fbHeight);
    size_t topologyUploads() const { return topologyUploads_; }
    size_t tornEdges() const { return fringe_.edges.size(); } // drawn with a fringe (last topology seen)
    size_t dynamicUploads() const { return dynamicUploads_; } // frames whose positions and normals were uploaded
    size_t clothTriangles() const { return frame_.clothIndices / 3; } // the cloth's triangles in the last frame (render_lod.h)
    // The cloth was replaced by a restored state whose topology revision may equal the one drawn
    // (an undo): upload the topology again on the next draw.
    void invalidateTopology() {
        mesh_.revision = fringe_.revision = coarseRevision_ = ~uint64_t(0);
        drawn_ = overlayDrawn_ = DrawnState{};
    }

private:
    // What prepare() saw of the world that submit() needs: the frame's whole input besides the GL
    // objects.
    struct Frame {
        RenderOptions options;
        View view;
        bool ground = false;
        float groundHeight = 0.f;
        bool cloth = false, shadow = false, inspect = false;
        bool coarse = false;     // the cloth's coarse indices (clothCoarseEbo_), else its fine ones
        size_t clothIndices = 0; // drawn from that buffer
        float strainMax = 0.5f;
        size_t fringeIndices = 0;
        std::vector<std::pair<Vec3, float>> balls; // centre, radius
        bool overlays = false;
        GLsizei weakPoints = 0, pinnedPoints = 0; // in pointsEbo_: the weak ones, then the pinned
    };
    void prepareCloth(const World& world);
    void prepareFringe(const World& world);
    void prepareOverlays(const World& world);
    void bindClothIndices();
    void drawGround();
    void drawCloth();
    void drawShadow();
    void drawFringe();
    void drawBalls();
    void drawOverlays();
    void setLighting(GLuint program);
    void buildSphere();

    Frame frame_;

    GLuint clothProgram_ = 0, clothInspectProgram_ = 0, litProgram_ = 0, groundProgram_ = 0, linesProgram_ = 0,
           fringeProgram_ = 0, shadowProgram_ = 0;
    // cloth
    GLuint clothVao_ = 0, clothUvVbo_ = 0, clothDynamicVbo_ = 0, clothEbo_ = 0, clothCoarseEbo_ = 0;
    GLuint texture_ = 0;
    RenderMesh mesh_;
    // clothEbo_ holds mesh_.indices; clothCoarseEbo_ the coarse indices of a grid cloth seen from far
    // (render_lod.h), made only when a frame wants them (coarseRevision_: the topology they are of).
    // A frame draws frame_.clothIndices indices of one of the two (frame_.coarse).
    std::vector<uint32_t> coarse_;
    uint64_t coarseRevision_ = ~uint64_t(0);
    std::vector<Vec3> normals_;
    std::vector<float> strain_;
    std::vector<float> dynamic_;
    size_t topologyUploads_ = 0;
    // What the uploaded positions (and normals) show: a frame that stepped nothing (paused, the
    // timeline held) reuses them instead of recomputing and uploading the same arrays.
    struct DrawnState {
        uint64_t steps = ~uint64_t(0), topology = ~uint64_t(0);
        double time = -1;
        size_t particles = 0;
        bool strain = false;
        bool operator==(const DrawnState&) const = default;
    };
    static DrawnState drawnState(const World& world, bool strain);
    DrawnState drawn_, overlayDrawn_;
    size_t dynamicUploads_ = 0;
    // the fringe of torn threads: rebuilt with the topology, vertices every frame
    GLuint fringeVao_ = 0, fringeVbo_ = 0, fringeEbo_ = 0;
    FringeMesh fringe_;
    std::vector<float> fringeVertices_;
    std::vector<uint32_t> fringeIndices_;
    // overlays: particle positions + line/point index buffers
    GLuint overlayVao_ = 0, particleVbo_ = 0, structuralEbo_ = 0, bendEbo_ = 0, pointsEbo_ = 0;
    uint64_t overlayRevision_ = ~uint64_t(0);
    size_t overlayParticles_ = 0;
    GLsizei structuralCount_ = 0, bendCount_ = 0;
    std::vector<uint32_t> pointScratch_;
    // ground and balls
    GLuint groundVao_ = 0, groundVbo_ = 0;
    GLuint sphereVao_ = 0, sphereVbo_ = 0, sphereEbo_ = 0;
    GLsizei sphereIndexCount_ = 0;
};

} // namespace clothtear::app
