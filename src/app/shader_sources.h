// GLSL sources from shaders/*.glsl, embedded at build time (embed_shaders.cmake).
#pragma once

namespace clothtear::app {

// The source of shaders/<name> (e.g. "cloth.vert.glsl"), or nullptr.
const char* shaderSource(const char* name);

} // namespace clothtear::app
