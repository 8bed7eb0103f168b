// Plain data across the boundary: Python dicts and lists <-> nlohmann::json, through Python's json module.
#pragma once

#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

namespace fabguide::bindings {

inline nlohmann::json toJson(const pybind11::object& value)
{
    const std::string text = pybind11::module_::import("json").attr("dumps")(value).cast<std::string>();
    return nlohmann::json::parse(text);
}

inline pybind11::object fromJson(const nlohmann::json& value)
{
    return pybind11::module_::import("json").attr("loads")(value.dump());
}

}  // namespace fabguide::bindings
