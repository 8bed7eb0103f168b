// The lists that messages name: "'a', 'b', 'c'".
#pragma once

#include <string>

namespace fabguide {

/// Each item as `text` gives it, `separator` between them.
template <class Items, class Text>
std::string joined(const Items& items, Text text, const std::string& separator = ", ")
{
    std::string all;
    bool first = true;
    for (const auto& item : items) {
        all += (first ? "" : separator) + std::string(text(item));
        first = false;
    }
    return all;
}

/// A text as it is: joined(texts, asIs, "; ").
inline const std::string& asIs(const std::string& text)
{
    return text;
}

/// Texts, ", " between them.
template <class Items>
std::string joined(const Items& texts)
{
    return joined(texts, asIs);
}

/// A name as messages quote it: 'name'.
inline std::string quoted(const std::string& name)
{
    return "'" + name + "'";
}

}  // namespace fabguide
