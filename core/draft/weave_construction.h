#pragma once
// What a weaver calls a weave (U3M's `construction`, docs/EXPORT.md): plain weave, a twill and
// its direction, a satin, or a dobby or jacquard draft for the rest.
#include <string>

#include "weave_pattern.h"

namespace woven {

enum class Construction { Plain, TwillLeft, TwillRight, Satin, Dobby, Jacquard };

// Read from the face's tile as its texture shows it (row V = 0 at the top, U to the right):
//   plain weave  every neighbour of a cell, along a row or a column, has the other yarn on top;
//   twill        each row is the one above it shifted by one thread: right hand (Z) when the
//                diagonal rises to the right ("/"), left hand (S) when it rises to the left;
//   satin        each row is the one above it shifted by a step of 2 or more, prime to the
//                repeat, with one interlacing a row and column (a five-end satin or more);
//   dobby        any other weave of at most kDobbyShafts distinct ends (a dobby loom's shafts);
//   jacquard     more.
Construction construction(const WeavePattern& face);
constexpr int kDobbyShafts = 24;

// U3M 1.1's name of it: "Plain weave", "Twill - right hand (Z)", "Satin", ...
const char* u3mConstructionName(Construction c);

}  // namespace woven
