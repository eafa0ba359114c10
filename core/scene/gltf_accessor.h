#pragma once
// Reading a glTF accessor into a plain array, whatever its storage: every component type,
// normalized integers (KHR_mesh_quantization), interleaved buffer views, sparse substitution.
// Every read is bounds-checked against its buffer view and buffer.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace woven {

// A malformed accessor; the message says which one and why (the caller adds the file name).
struct AccessorError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct AccessorData {
    std::vector<double> values;  // count x components; doubles hold every uint32 index exactly
    int components = 0;
    size_t count = 0;
    double at(size_t element, int component) const { return values[element * components + component]; }
};

// Normalized integer accessors are mapped to [0, 1] or [-1, 1] as glTF 2.0 section 3.11 says;
// other integers keep their value.
AccessorData readAccessor(const tinygltf::Model& model, int accessorIndex);

}  // namespace woven
