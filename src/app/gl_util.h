// Small OpenGL helpers: compiling the embedded shaders into programs, uniform setters.
#pragma once
#include "clothtear/types.h"

#include <GL/glew.h>
#include <array>
#include <initializer_list>
#include <string>

namespace clothtear::app {

// Compiles shaders/<vertex> and shaders/<fragment> (embedded sources) and links them.
// The error names the shader and carries the driver's log.
Result<GLuint> buildProgram(const char* vertexName, const char* fragmentName);

// Float vertex attributes read from the bound GL_ARRAY_BUFFER, interleaved in the order of `sizes`
// (components each) at locations first, first + 1, ...: one call describes one buffer's layout.
inline void floatAttributes(std::initializer_list<int> sizes, GLuint first = 0) {
    int floats = 0;
    for (int s : sizes) floats += s;
    GLuint location = first;
    size_t at = 0;
    for (int s : sizes) {
        glEnableVertexAttribArray(location);
        glVertexAttribPointer(location, s, GL_FLOAT, GL_FALSE, GLsizei(floats * sizeof(float)),
                              reinterpret_cast<void*>(at * sizeof(float)));
        ++location;
        at += size_t(s);
    }
}

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
