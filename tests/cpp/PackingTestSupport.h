// Helpers shared by the packing tests: building parts and checking layouts independently.
#pragma once

#include "Layout/Docking.h"
#include "Layout/Pack.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace fabguide::material::testing {

inline RasterPart rectanglePart(const std::string& name, int w, int h, bool turnable = true)
{
    RasterPart part{name, {Footprint::rectangle(w, h)}, {0}};
    if (turnable && w != h) {
        part.shapes.push_back(part.shapes[0].rotated90());
        part.rotations.push_back(90);
    }
    return part;
}

inline std::vector<RasterPart> randomParts(int count, int maxSide, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> side(1, maxSide);
    std::vector<RasterPart> parts;
    for (int i = 0; i < count; ++i)
        parts.push_back(rectanglePart("p" + std::to_string(i), side(random), side(random)));
    return parts;
}

/// Random blobs: each cell of a random box filled with probability 0.7 (the first cell always), so columns
/// hold several runs and parts have holes and overhangs.
inline std::vector<RasterPart> randomBlobs(int count, int maxSide, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> side(1, maxSide);
    std::bernoulli_distribution filled(0.7);
    std::vector<RasterPart> parts;
    for (int i = 0; i < count; ++i) {
        const int w = side(random), h = side(random);
        std::vector<std::uint8_t> cells(static_cast<size_t>(w) * h);
        for (std::uint8_t& cell : cells)
            cell = &cell == cells.data() || filled(random);
        const Footprint shape(w, h, std::move(cells));
        parts.push_back({"b" + std::to_string(i), {shape, shape.rotated90()}, {0, 90}});
    }
    return parts;
}

/// Every part placed once, inside its sheet, on no other part's cells.
inline void expectValidLayout(const GridLayout& layout, const std::vector<RasterPart>& parts,
                              const std::vector<BoardStock>& stock)
{
    ASSERT_EQ(layout.placed.size(), parts.size());
    std::vector<std::vector<int>> owner(layout.stock.size());
    for (size_t s = 0; s < layout.stock.size(); ++s)
        owner[s].assign(static_cast<size_t>(stock[layout.stock[s]].width) * stock[layout.stock[s]].height,
                        -1);
    std::vector<int> seen(parts.size(), 0);
    for (const Placed& p : layout.placed) {
        ++seen[p.part];
        const Footprint& f = parts[p.part].shapes[p.shape];
        const BoardStock& board = stock[layout.stock[p.sheet]];
        ASSERT_TRUE(p.x >= 0 && p.y >= 0 && p.x + f.width() <= board.width &&
                    p.y + f.height() <= board.height)
            << parts[p.part].name << " leaves its sheet";
        for (int y = 0; y < f.height(); ++y)
            for (int x = 0; x < f.width(); ++x)
                if (f.filled(x, y)) {
                    int& cell = owner[p.sheet][static_cast<size_t>(p.y + y) * board.width + p.x + x];
                    ASSERT_EQ(cell, -1) << parts[p.part].name << " overlaps part " << cell;
                    cell = p.part;
                }
    }
    for (size_t i = 0; i < parts.size(); ++i)
        EXPECT_EQ(seen[i], 1) << parts[i].name;
}

/// Every placement inside its sheet's trim and `kerf + spacing` from every other on its sheet; every unit
/// placed once.
inline void expectValid(const PackProblem& problem, const Layout& layout)
{
    const PackSettings& s = problem.settings;
    const double gap = s.kerf + s.spacing, eps = 1e-9;
    std::vector<int> placed(problem.parts.size(), 0);
    for (size_t i = 0; i < layout.placements.size(); ++i) {
        const Placement& a = layout.placements[i];
        const MasterBoard& sheet = layout.sheets[a.sheet];
        ++placed[a.part];
        EXPECT_GE(a.x, s.trim - eps);
        EXPECT_GE(a.y, s.trim - eps);
        EXPECT_LE(a.x + a.width, sheet.width - s.trim + eps) << problem.parts[a.part].id;
        EXPECT_LE(a.y + a.height, sheet.height - s.trim + eps) << problem.parts[a.part].id;
        for (size_t j = i + 1; j < layout.placements.size(); ++j) {
            const Placement& b = layout.placements[j];
            EXPECT_TRUE(a.sheet != b.sheet || a.x + a.width + gap <= b.x + eps ||
                        b.x + b.width + gap <= a.x + eps || a.y + a.height + gap <= b.y + eps ||
                        b.y + b.height + gap <= a.y + eps)
                << problem.parts[a.part].id << " and " << problem.parts[b.part].id << " on sheet " << a.sheet;
        }
    }
    for (size_t p = 0; p < problem.parts.size(); ++p)
        EXPECT_EQ(placed[p], problem.parts[p].quantity) << problem.parts[p].id;
}

inline double distance(geometry::Point2 p, geometry::Point2 a, geometry::Point2 b)
{
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

/// The least distance between two polygons that do not overlap: from a vertex of one to an edge of the other.
inline double distance(const geometry::Polygon& a, const geometry::Polygon& b)
{
    double least = HUGE_VAL;
    for (const auto& [from, to] : {std::pair{&a, &b}, std::pair{&b, &a}})
        for (const geometry::Point2& p : *from)
            for (size_t k = 0; k < to->size(); ++k)
                least = std::min(least, distance(p, (*to)[k], (*to)[(k + 1) % to->size()]));
    return least;
}

/// Oak stiles that follow its grain (along the board's height) and a hardboard back: each part has one board
/// kind of its thickness, and the stiles one turn on it.
inline PackProblem grainAndThicknessJob()
{
    PackProblem problem;
    problem.boards.push_back({"oak", "oak", 1000, 2000, 18, -1, Grain::AlongHeight});
    problem.boards.push_back({"hardboard", "hdf", 1000, 1000, 6, -1});
    PartSpec stile = rectangularPart("stile", 800, 60, 4);
    stile.followsGrain = true;
    stile.thickness = 18;
    PartSpec back = rectangularPart("back", 900, 900, 1);
    back.thickness = 6;
    problem.parts = {stile, back};
    return problem;
}

/// The stiles of grainAndThicknessJob turned along the grain, every part on a board of its thickness.
inline void expectGrainAndThicknessKept(const PackProblem& problem, const Layout& layout)
{
    for (const Placement& p : layout.placements) {
        EXPECT_EQ(layout.sheets[p.sheet].thickness, problem.parts[p.part].thickness);
        if (p.part == 0) {
            EXPECT_EQ(p.rotation % 180, 90) << "the stile's length runs along the board's grain (its height)";
        }
    }
}

/// `sheets` whole 2440 x 1220 boards cut in three stages at random (slabs across, columns in a slab, pieces
/// in a column, none under 150 mm), each piece less the kerf and then times `slack` (to 0.1 mm): parts that
/// fit on `sheets` boards by construction, in a shuffled order.
inline PackProblem cutFromSheets(unsigned seed, int sheets, double slack)
{
    PackProblem problem;
    problem.boards.push_back({"board", "ply", 2440, 1220, 18, -1});
    problem.settings.kerf = 3.2;
    problem.settings.trim = 10;
    const double kerf = problem.settings.kerf, width = 2440 - 20 + kerf, height = 1220 - 20 + kerf;
    std::mt19937 random(seed);
    const auto tenths = [](double mm) { return std::floor(mm * 10 + 1e-6) / 10; };  // rounded down
    // Cuts `length` into pieces of `from`-`to`, the last one taking what is left under `from`.
    const auto pieces = [&](double length, double from, double to) {
        std::vector<double> cut;
        for (double at = 0; at < length;) {
            double piece = std::round(std::uniform_real_distribution<double>(from, to)(random));
            if (length - at - piece < from)
                piece = length - at;
            cut.push_back(piece), at += piece;
        }
        return cut;
    };
    for (int sheet = 0; sheet < sheets; ++sheet)
        for (double slab : pieces(height, 150, 600))
            for (double column : pieces(width, 150, 900))
                for (double piece : pieces(slab, 150, slab))
                    problem.parts.push_back(rectangularPart("p" + std::to_string(problem.parts.size()),
                                                            tenths((column - kerf) * slack),
                                                            tenths((piece - kerf) * slack)));
    std::shuffle(problem.parts.begin(), problem.parts.end(), random);
    return problem;
}

}  // namespace fabguide::material::testing
