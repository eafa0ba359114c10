#include "choice_check.h"

#include <algorithm>

namespace woven {

CLI::Validator oneOf(const std::vector<std::string>& names) {
    std::string list;
    for (size_t i = 0; i < names.size(); ++i) list += (i ? (i + 1 == names.size() ? " or " : ", ") : "") + names[i];
    return CLI::Validator(
        [names, list](std::string& text) {
            if (std::find(names.begin(), names.end(), text) != names.end()) return std::string();
            return "'" + text + "' is not one of " + list;
        },
        list);
}

}  // namespace woven
