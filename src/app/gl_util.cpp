// Shader compilation with readable errors.
#include "gl_util.h"

#include "shader_sources.h"

#include <algorithm>
#include <vector>

namespace clothtear::app {
namespace {

Result<GLuint> compile(GLenum type, const char* name) {
    const char* source = shaderSource(name);
    if (!source) return Result<GLuint>::failure(std::string("shader ") + name + " is not embedded in this build");
    const GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
        std::vector<char> log(size_t(std::max(len, 1)));
        glGetShaderInfoLog(s, len, nullptr, log.data());
        glDeleteShader(s);
        return Result<GLuint>::failure(std::string("shaders/") + name + ": " + log.data());
    }
    return Result<GLuint>{s, {}};
}

} // namespace

Result<GLuint> buildProgram(const char* vertexName, const char* fragmentName) {
    Result<GLuint> vs = compile(GL_VERTEX_SHADER, vertexName);
    if (!vs.ok()) return vs;
    Result<GLuint> fs = compile(GL_FRAGMENT_SHADER, fragmentName);
    if (!fs.ok()) {
        glDeleteShader(vs.value);
        return fs;
    }
    const GLuint p = glCreateProgram();
    glAttachShader(p, vs.value);
    glAttachShader(p, fs.value);
    glLinkProgram(p);
    glDeleteShader(vs.value);
    glDeleteShader(fs.value);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(p, GL_INFO_LOG_LENGTH, &len);
        std::vector<char> log(size_t(std::max(len, 1)));
        glGetProgramInfoLog(p, len, nullptr, log.data());
        glDeleteProgram(p);
        return Result<GLuint>::failure(std::string("linking ") + vertexName + " + " + fragmentName + ": " + log.data());
    }
    return Result<GLuint>{p, {}};
}

} // namespace clothtear::app
