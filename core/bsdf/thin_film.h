#pragma once
// KHR_materials_iridescence's Fresnel term: the reflectance of a thin dielectric film over the
// base, with the interference of its inter-reflections integrated over the visible spectrum in
// closed form (Belcour and Barla 2017, "A Practical Extension to Microfacet Theory for the
// Modeling of Varying Iridescence", as the extension's implementation notes approximate it:
// Schlick reflectances at both interfaces, no polarisation, two orders of the Fourier series).
// shaders/gltf_iridescence.glsl is its twin.
#include <glm/glm.hpp>

namespace woven {

// Linear Rec. 709 reflectance seen from a medium of index `outsideIor` at angle cosTheta
// (to the microfacet normal) through a film of index `filmIor` and thickness `thicknessNm`
// over a base whose normal-incidence reflectance is `baseF0`. Total internal reflection in
// the film reflects everything.
glm::vec3 thinFilmFresnel(float outsideIor, float filmIor, float cosTheta, float thicknessNm, const glm::vec3& baseF0);

}  // namespace woven
