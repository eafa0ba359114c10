#pragma once
// A linked GLSL program built from files in the shaders/ directory. The sources of each stage
// are concatenated after a common preamble (version line, feature #defines, generated
// declarations), with #line directives so compile errors name the right file and line.
#include <epoxy/gl.h>

#include <string>
#include <vector>

namespace woven {

// $WOVEN_SHADER_DIR when set, else the source tree's shaders/ (compiled in).
std::string shaderDirectory();

class ShaderProgram {
public:
    // Throws GlError naming the file and quoting the compiler's log.
    ShaderProgram(const std::vector<std::string>& vertexFiles, const std::vector<std::string>& fragmentFiles,
                  const std::string& preamble = "");
    ~ShaderProgram();
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    GLuint id() const { return program_; }
    GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }

private:
    GLuint program_ = 0;
};

}  // namespace woven
