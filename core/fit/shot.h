#pragma once
// One shot of `woven fit` (docs/FIT.md): a woven scene file with a "photo" key, its photograph
// decoded to linear RGB at the render's size, and the part of the scene (--target) whose woven
// material the fit recovers. Loading checks everything the fit needs before any rendering, and
// every refusal is a FitError whose message starts with the shot's file.
#include <glm/glm.hpp>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene_description.h"

namespace woven {

struct FitError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Shot {
    std::string path;  // the scene file
    std::shared_ptr<const SceneDescription> scene;  // the target made woven
    ShotPhoto photo;
    Image image;  // the photograph, linear RGB, at the render's size
    std::vector<size_t> meshes;   // the target's meshes
    std::vector<int> materials;   // the woven materials they use (indices into scene->materials)
    // d(u, v) / d(x, y) at the image centre, where the camera's central ray meets the target:
    // columns are per pixel along x (right) and y (down). How the weave's threads per UV unit
    // become cycles per pixel in the photo.
    glm::dmat2 uvPerPixel{1.0};
    // Every light of the shot (punctual, or an emissive surface such as a light box) lies behind
    // the target as the camera sees it (and the environment is black): the photo shows only light
    // through the cloth, and the fit solves the transmission (transmission, transmission_gloss)
    // from it, not the colours.
    bool backlit = false;
};

// U's and V's gradients in the image, per pixel (x right, y down): the rows of uvPerPixel, which
// the warp ends' and the weft picks' frequencies follow.
inline glm::dvec2 gradientU(const glm::dmat2& uvPerPixel) { return {uvPerPixel[0][0], uvPerPixel[1][0]}; }
inline glm::dvec2 gradientV(const glm::dmat2& uvPerPixel) { return {uvPerPixel[0][1], uvPerPixel[1][1]}; }

// The shot with its target's weave turned by `radians` in the image, as the cloth lay turned in
// the photo (threadTurn() of its peaks): the target's UVs rotated about their mean, their tangents
// dropped so that the renderer's own follow the UVs, and uvPerPixel rotated alike.
Shot turnedShot(const Shot& shot, double radians);

// Throws FitError naming the file: no "photo" key, a target that names nothing, an image that is
// missing, cannot be decoded or whose size differs from the render's, a target the image centre
// does not see.
Shot loadShot(const std::string& path, const std::string& target);

}  // namespace woven
