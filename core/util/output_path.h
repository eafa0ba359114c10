#pragma once
// An output never replaces an input: `woven export scene.gltf -o scene.gltf` overwrote the file it
// had just read, and `woven render x.gltf -o texture.png` would replace one of its textures.
#include <string>
#include <vector>

#include "atomic_file.h"

namespace woven {

// Whether the two paths name one existing file (through any spelling or link).
bool sameFile(const std::string& a, const std::string& b);

// Throws FileWriteError naming `out` and the input it would replace when `out` is one of `inputs`.
void refuseOverwritingInputs(const std::string& out, const std::vector<std::string>& inputs);

}  // namespace woven
