// Small OpenGL helpers: compiling the embedded shaders into programs, uniform setters.
#pragma once
#include "clothtear/types.h"

#include <GL/glew.h>
#include <array>
#include <string>

namespace clothtear::app {

// Compiles shaders/<vertex> and shaders/<fragment> (embedded sources) and links them.
// The error names the shader and carries the driver's log.
Result<GLuint> buildProgram(const char* vertexName, const char* fragmentName);

inline GLint uniform(GLuint program, const char* name) { return glGetUniformLocation(program, name); }
inline void setVec3(GLuint program, const char* name, const std::array<float, 3>& v) {
    glUniform3f(uniform(program, name), v[0], v[1], v[2]);
}
inline void setVec3(GLuint program, const char* name, const Vec3& v) {
    glUniform3f(uniform(program, name), v.x(), v.y(), v.z());
}
inline void setFloat(GLuint program, const char* name, float v) { glUniform1f(uniform(program, name), v); }
inline void setInt(GLuint program, const char* name, int v) { glUniform1i(uniform(program, name), v); }
inline void setMat4(GLuint program, const char* name, const float* columnMajor) {
    glUniformMatrix4fv(uniform(program, name), 1, GL_FALSE, columnMajor);
}

} // namespace clothtear::app
