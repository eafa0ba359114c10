#pragma once
// Reading a WIF 1.1 file (Weaving Information File, the format weaving programs exchange
// drafts in) into a Draft, robust to what real files hold. The rules (which section wins, what
// is ignored with a warning, the size limits) are in docs/DRAFTS.md.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "draft.h"

namespace woven {

// Larger files are refused before they are read; real drafts are well under 1 MiB.
constexpr size_t kMaxWifFileBytes = size_t(64) << 20;

// Throws DraftError, naming the file (and the line where there is one), for a file that cannot
// be read as a draft. Whatever is read but ignored or approximated adds one line to `warnings`
// per kind and section; each line starts with the file name.
Draft readWif(const std::string& path, std::vector<std::string>& warnings);

// The same for a file's contents; `name` stands for the file in messages.
Draft parseWif(std::string_view text, const std::string& name, std::vector<std::string>& warnings);

}  // namespace woven
