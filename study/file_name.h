#pragma once
// A name (a shader's, a view's, an input's) as one component of a file name: letters, digits,
// '.', '-' and '_' kept, anything else '_', never empty or hidden.

#include <cctype>
#include <string>

namespace qs::study {

inline std::string file_name(std::string name) {
    for (char& c : name) {
        if (!std::isalnum((unsigned char)c) && c != '.' && c != '-' && c != '_') c = '_';
    }
    if (name.empty() || name[0] == '.') name.insert(name.begin(), '_');
    return name;
}

}  // namespace qs::study
