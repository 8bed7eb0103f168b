#include "Layout/Footprint.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace fabguide::material {

Footprint Footprint::rectangle(int width, int height)
{
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("a part must be at least one grid cell wide and high, got " +
                                    std::to_string(width) + " x " + std::to_string(height));
    Footprint solid;
    solid.width_ = width;
    solid.height_ = height;
    solid.area_ = static_cast<long>(width) * height;
    solid.left_.assign(height, 0);
    solid.right_.assign(height, width);
    solid.bottom_.assign(width, 0);
    solid.top_.assign(width, height);
    solid.runs_.assign(width, {0, height});
    for (int c = 0; c <= width; ++c)
        solid.runStart_.push_back(c);
    return solid;
}

Footprint::Footprint(int width, int height, std::vector<std::uint8_t> cells)
    : width_(width),
      height_(height),
      cells_(std::make_shared<const std::vector<std::uint8_t>>(std::move(cells))),
      left_(height, width),
      right_(height, 0),
      bottom_(width, height),
      top_(width, 0)
{
    if (width <= 0 || height <= 0 || cells_->size() != static_cast<size_t>(width) * height)
        throw std::invalid_argument("footprint bitmap does not match its size");
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x)
            if (filled(x, y)) {
                ++area_;
                left_[y] = std::min(left_[y], x);
                right_[y] = std::max(right_[y], x + 1);
                bottom_[x] = std::min(bottom_[x], y);
                top_[x] = std::max(top_[x], y + 1);
            }
    if (area_ == 0)
        throw std::invalid_argument("footprint has no filled cell");
    for (int x = 0; x < width_; ++x) {
        runStart_.push_back(static_cast<int>(runs_.size()));
        for (int y = 0; y < height_; ++y)
            if (filled(x, y) && (y == 0 || !filled(x, y - 1)))
                runs_.push_back({y, y + 1});
            else if (filled(x, y))
                ++runs_.back().second;
    }
    runStart_.push_back(static_cast<int>(runs_.size()));
    if (area_ == static_cast<long>(width_) * height_)
        cells_.reset();  // solid: one representation for every full rectangle
}

Footprint Footprint::rotated90() const
{
    if (!cells_)
        return rectangle(height_, width_);
    // Counter-clockwise: cell (x, y) goes to (height - 1 - y, x).
    std::vector<std::uint8_t> turned(cells_->size());
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x)
            turned[static_cast<size_t>(x) * height_ + (height_ - 1 - y)] =
                (*cells_)[static_cast<size_t>(y) * width_ + x];
    return Footprint(height_, width_, std::move(turned));
}

}  // namespace fabguide::material
