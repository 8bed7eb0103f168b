#include "Layout/Lettering.h"

extern "C" {  // a C library without C++ guards
#include <hersheyfont.h>
}

#include <cmath>
#include <memory>
#include <stdexcept>

namespace fabguide::material {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEm = 32;        // font units per em: its capitals are 21 high, its letters about 19 wide
constexpr double kMiddle = 10.5;  // font units above the baseline: the middle of the capitals
constexpr const char* kFont = "futural";  // Simplex Roman: one stroke per line, as engravers use

const hershey_font& font()
{
    static const std::unique_ptr<hershey_font, void (*)(hershey_font*)> loaded(hershey_font_load(kFont),
                                                                               hershey_font_free);
    if (!loaded)
        throw std::runtime_error(std::string("labels as strokes: the Hershey font '") + kFont +
                                 "' is not installed (Debian package hershey-fonts-data)");
    return *loaded;
}

const hershey_glyph& glyph(char c)
{
    const unsigned char code = c >= 32 && c < 127 ? static_cast<unsigned char>(c) : '?';
    return font().glyphs[code];
}

}  // namespace

std::vector<geometry::Polygon> strokes(const Label& label)
{
    double advance = 0;
    for (char c : label.text)
        advance += glyph(c).width;
    const double scale = label.height / kEm, turn = label.angle * kPi / 180;
    const double cosine = std::cos(turn), sine = std::sin(turn);
    std::vector<geometry::Polygon> lines;
    double x = -advance / 2;
    for (char c : label.text) {
        const hershey_glyph& g = glyph(c);
        for (const hershey_path* path = g.paths; path; path = path->next) {
            geometry::Polygon line;
            for (unsigned short k = 0; k < path->nverts; ++k) {
                const double u = (x + path->verts[k].x) * scale, v = (path->verts[k].y - kMiddle) * scale;
                line.push_back({label.at.x + u * cosine - v * sine, label.at.y + u * sine + v * cosine});
            }
            lines.push_back(std::move(line));
        }
        x += g.width;
    }
    return lines;
}

}  // namespace fabguide::material
