#include "shader_program.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "gl_error.h"

namespace woven {

namespace {

std::string readShaderFile(const std::string& name) {
    const std::string path = shaderDirectory() + "/" + name;
    std::ifstream in(path);
    if (!in) throw GlError("cannot read shader '" + path + "' (set WOVEN_SHADER_DIR to the shaders/ directory)");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The GLSL log says "0:LINE(COL)" or "FILE:LINE": #line gives each file its own source number,
// listed here so a reader can map numbers to names.
GLuint compile(GLenum stage, const std::vector<std::string>& files, const std::string& preamble) {
    std::string source = "#version 410 core\n" + preamble;
    std::string legend = "source 0 = preamble";
    for (size_t i = 0; i < files.size(); ++i) {
        source += "#line 1 " + std::to_string(i + 1) + "\n" + readShaderFile(files[i]) + "\n";
        legend += ", " + std::to_string(i + 1) + " = " + files[i];
    }
    GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::string log(size_t(std::max(length, 1)), '\0');
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        glDeleteShader(shader);
        throw GlError("shader compilation failed (" + legend + "):\n" + log);
    }
    return shader;
}

}  // namespace

std::string shaderDirectory() {
    if (const char* dir = std::getenv("WOVEN_SHADER_DIR")) return dir;
    return WOVEN_SHADER_DIR;
}

ShaderProgram::ShaderProgram(const std::vector<std::string>& vertexFiles,
                             const std::vector<std::string>& fragmentFiles, const std::string& preamble) {
    GLuint vs = compile(GL_VERTEX_SHADER, vertexFiles, preamble);
    GLuint fs;
    try {
        fs = compile(GL_FRAGMENT_SHADER, fragmentFiles, preamble);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    program_ = glCreateProgram();
    glAttachShader(program_, vs);
    glAttachShader(program_, fs);
    glLinkProgram(program_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program_, GL_INFO_LOG_LENGTH, &length);
        std::string log(size_t(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program_, length, nullptr, log.data());
        glDeleteProgram(program_);
        throw GlError("shader link failed:\n" + log);
    }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(program_); }

}  // namespace woven
