#pragma once
// Writing a Draft as a WIF 1.1 file that weaving programs (Fiberworks, WeaveIt,
// Handweaving.net, ...) open: the sections they expect, colours as 0..255 sRGB in a palette,
// CR LF line ends. Reading the file back gives the same draft, as long as its colours are
// 8-bit sRGB values (wif_reader.h).
#include <string>

#include "draft.h"

namespace woven {

// Throws DraftError (prefixed by `name`) for a draft that breaks validate() or has no
// interlacement, which no reader could use.
std::string formatWif(const Draft& draft, const std::string& name);

// formatWif(draft, path), written atomically (atomic_file.h): `path` never holds half a file.
// Throws DraftError as formatWif does, FileWriteError when the file cannot be written.
void writeWif(const std::string& path, const Draft& draft);

}  // namespace woven
