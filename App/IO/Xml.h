// XML text for the files FabGuide writes (SVG cut sheets, 3MF models).
#pragma once

#include <string>

namespace fabguide::io {

/// text with &, <, > and " escaped, for an element's text or an attribute's value.
std::string escapeXml(const std::string& text);

}  // namespace fabguide::io
