#include "agglo/io/dataset_json.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>

namespace agglo::io {

namespace {

nlohmann::json real_to_json(double x) {
  if (std::isfinite(x)) return x;
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return fmt::format("nan:{:016x}", std::bit_cast<std::uint64_t>(x));
}

double real_from_json(const nlohmann::json& v) {
  if (v.is_number()) return v.get<double>();
  const std::string s = v.is_string() ? v.get<std::string>() : std::string();
  if (s == "inf") return HUGE_VAL;
  if (s == "-inf") return -HUGE_VAL;
  if (s.size() == 20 && s.rfind("nan:", 0) == 0) return std::bit_cast<double>(std::stoull(s.substr(4), nullptr, 16));
  throw std::invalid_argument("dataset JSON: '" + v.dump() + "' is not a real value");
}

nlohmann::json variable_to_json(const Variable& v) {
  nlohmann::json values = nlohmann::json::array();
  if (v.integer) values = v.ints;
  else
    for (double x : v.reals) values.push_back(real_to_json(x));
  return {{"name", v.name},       {"dims", v.dims},       {"units", v.units},          {"long_name", v.long_name},
          {"integer", v.integer}, {"values", values},     {"attributes", v.attributes}};
}

}  // namespace

nlohmann::json dataset_to_json(const Dataset& d) {
  nlohmann::json dims = nlohmann::json::array(), vars = nlohmann::json::array();
  for (const auto& [name, length] : d.dims) dims.push_back({name, length});
  for (const auto& v : d.variables) vars.push_back(variable_to_json(v));
  return {{"dims", dims}, {"variables", vars}, {"attributes", d.attributes}};
}

Dataset dataset_from_json(const nlohmann::json& j) {
  if (!j.is_object() || !j.contains("dims") || !j.contains("variables"))
    throw std::invalid_argument("dataset JSON: an object with \"dims\" and \"variables\" is required");
  Dataset d;
  try {
    for (const auto& dim : j.at("dims")) d.add_dim(dim.at(0).get<std::string>(), dim.at(1).get<std::size_t>());
    for (const auto& v : j.at("variables")) {
      const auto name = v.at("name").get<std::string>();
      auto dims = v.at("dims").get<std::vector<std::string>>();
      auto units = v.at("units").get<std::string>(), long_name = v.at("long_name").get<std::string>();
      Variable* added = nullptr;
      if (v.at("integer").get<bool>()) {
        added = &d.add_ints(name, dims, units, long_name, v.at("values").get<std::vector<std::int64_t>>());
      } else {
        std::vector<double> reals;
        for (const auto& x : v.at("values")) reals.push_back(real_from_json(x));
        added = &d.add(name, dims, units, long_name, std::move(reals));
      }
      added->attributes = v.value("attributes", nlohmann::json::object());
    }
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("dataset JSON: ") + e.what());
  } catch (const std::logic_error& e) {
    throw std::invalid_argument(std::string("dataset JSON: ") + e.what());
  }
  d.attributes = j.value("attributes", nlohmann::json::object());
  return d;
}

}  // namespace agglo::io
