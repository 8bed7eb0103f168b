// Text for the files FabGuide writes (SVG cut sheets, 3MF models, DXF): names as users typed them, made safe.
#pragma once

#include <string>

namespace fabguide::io {

/// `text` as every file format takes it on one line: invalid UTF-8 and control characters (line breaks, tabs,
/// NUL) each become U+FFFD, the replacement character. XML 1.0 refuses them even escaped, and in a DXF a line
/// break inside a value shifts every group code after it.
std::string plainText(const std::string& text);

/// plainText with &, <, > and " escaped, for an element's text or an attribute's value.
std::string escapeXml(const std::string& text);

}  // namespace fabguide::io
