#pragma once
// The panel's Fabrics menu: a combo of the library's fabrics (assets/fabrics, docs/FABRICS.md),
// each beside a thumbnail of its drawdown in its thread colours, made into a GL texture once,
// when the menu is made.
#include <epoxy/gl.h>

#include <string>
#include <vector>

#include "material_json.h"
#include "scene_description.h"

namespace woven {

// A drawdown of the fabric's weave in its thread colours, one whole repeat of its weave and
// thread lists where that is 16 to 128 threads (more repeats of a small one, part of a larger),
// square, about `pixels` on a side.
Image fabricThumbnail(const MaterialJson& fabric, int pixels);

class FabricMenu {
public:
    // Reads the library (one that cannot be read: the menu says why instead) and uploads the
    // thumbnails: the window's GL context must be current, as it must be when it is destroyed.
    FabricMenu();
    ~FabricMenu();
    FabricMenu(const FabricMenu&) = delete;
    FabricMenu& operator=(const FabricMenu&) = delete;

    // The combo, showing `current` (a fabric's name; empty: none); the name chosen this frame, or empty.
    std::string draw(const char* label, const std::string& current);

private:
    struct Entry {
        std::string name, title, source;
        GLuint texture = 0;
    };
    std::vector<Entry> entries_;
    std::string error_;
};

}  // namespace woven
