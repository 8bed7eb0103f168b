// A part rasterised on the material-space grid, in one orientation (thesis 5.4.1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace fabguide::material {

/// A part's bitmap at grid resolution τ plus the four profiles the docking height-fields
/// need (thesis Fig. 5.14): per row, the first occupied column (`left`) and one past the last
/// (`right`); per column, the first occupied row (`bottom`) and one past the last (`top`).
/// An empty row has left = width, right = 0 (likewise columns), so it never constrains.
class Footprint {
public:
    /// A full w × h rectangle of cells, stored as its profiles only (design exploration makes many).
    static Footprint rectangle(int width, int height);
    /// From a row-major bitmap (row 0 at the bottom); throws std::invalid_argument if empty.
    Footprint(int width, int height, std::vector<std::uint8_t> cells);

    int width() const { return width_; }
    int height() const { return height_; }
    long area() const { return area_; }
    bool filled(int x, int y) const
    {
        return !cells_ || (*cells_)[static_cast<std::size_t>(y) * width_ + x] != 0;
    }

    const std::vector<int>& left() const { return left_; }
    const std::vector<int>& right() const { return right_; }
    const std::vector<int>& bottom() const { return bottom_; }
    const std::vector<int>& top() const { return top_; }

    /// The filled runs of column `c`, bottom up, as [first row, one past the last) pairs.
    struct Runs {
        const std::pair<int, int>* first;
        const std::pair<int, int>* last;
        const std::pair<int, int>* begin() const { return first; }
        const std::pair<int, int>* end() const { return last; }
    };
    Runs runs(int c) const { return {runs_.data() + runStart_[c], runs_.data() + runStart_[c + 1]}; }

    /// The same part turned counter-clockwise by 90°.
    Footprint rotated90() const;

    bool operator==(const Footprint& other) const
    {
        return width_ == other.width_ && height_ == other.height_ &&
               (cells_ == other.cells_ || (cells_ && other.cells_ && *cells_ == *other.cells_));
    }

private:
    Footprint() = default;
    int width_ = 0;
    int height_ = 0;
    /// Row-major; none when every cell is filled (a rectangle). Shared by copies: a part's copies (its
    /// quantity) take its bitmap's memory once.
    std::shared_ptr<const std::vector<std::uint8_t>> cells_;
    long area_ = 0;
    std::vector<int> left_, right_, bottom_, top_;
    std::vector<std::pair<int, int>> runs_;  ///< every column's runs, column by column
    std::vector<int> runStart_;              ///< column c's runs are runs_[runStart_[c] .. runStart_[c + 1])
};

}  // namespace fabguide::material
