#pragma once
// WIF texts the draft tests start from, and reading a text through a real file.
#include <string>
#include <vector>

#include "draft.h"

namespace woven::test {

// 2/2 twill: 4 shafts, straight draw, 4 treadles tied 12 23 34 41, treadled 1-4, 8 ends x 8
// picks, white warp, black weft, 0..255 palette.
std::string twillWif();
// The same weave's top-yarn map, rows = picks, drawn by hand.
std::vector<std::string> twillMap();

// Plain weave by lift plan only: 2 shafts, ends on 1, 2, 1, 2; picks lift 1, 2, 1, 2.
std::string plainLiftplanWif();
std::vector<std::string> plainMap();

// `text` with `from` (which must occur) replaced by `to`, every occurrence.
std::string replaced(std::string text, const std::string& from, const std::string& to);

// Writes `text` to a fresh temporary file called `fileName` and reads it with readWif.
Draft readText(const std::string& text, std::vector<std::string>& warnings,
               const std::string& fileName = "draft.wif");

// The top-yarn map of a draft, through draftTile().
std::vector<std::string> mapOf(const Draft& draft);

}  // namespace woven::test
