#pragma once
// What loadScene() says of a file, for the tests of what it refuses: its SceneError's message,
// or "(no error)" when the file loads.
#include <string>

#include "scene_loader.h"

namespace woven::test {

inline std::string loadError(const std::string& path, const LoadOptions& options = {}) {
    try {
        loadScene(path, options);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace woven::test
