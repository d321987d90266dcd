// Calls OpenGL (gl_renderer.cpp draws the scenes).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "reference/depth_mipmaps.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace qs {

std::vector<float> generated_depth_mipmaps(int width, int height, const std::vector<float>& depths) {
    if (width < 1 || height < 1 || depths.size() != std::size_t(width) * std::size_t(height)) {
        throw std::invalid_argument("generated_depth_mipmaps: " + std::to_string(depths.size()) + " depths for " +
                                    std::to_string(width) + "x" + std::to_string(height));
    }
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, width, height, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glGenerateMipmap(GL_TEXTURE_2D);
    std::vector<float> levels;
    for (int level = 1, w = width, h = height; w > 1 || h > 1; ++level) {
        w = std::max(1, w / 2), h = std::max(1, h / 2);
        const std::size_t at = levels.size();
        levels.resize(at + std::size_t(w) * std::size_t(h));
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glGetTexImage(GL_TEXTURE_2D, level, GL_DEPTH_COMPONENT, GL_FLOAT, levels.data() + at);
    }
    const GLenum error = glGetError();
    glDeleteTextures(1, &texture);
    if (error != GL_NO_ERROR) throw std::runtime_error("generated_depth_mipmaps: GL error " + std::to_string(error));
    return levels;
}

}  // namespace qs
