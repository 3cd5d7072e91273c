#include "reconfigured_parameters.hpp"

#include <dynamic_reconfigure/Config.h>

#include <boost/any.hpp>

#include <charconv>
#include <limits>
#include <sstream>

namespace eaci_ros {
namespace {

std::string textOf(const std::string& type, const boost::any& value) {
  std::ostringstream text;
  if (type == "int") text << boost::any_cast<int>(value);
  else if (type == "double") {
    text.precision(17);
    text << boost::any_cast<double>(value);
  }
  else if (type == "bool") text << (boost::any_cast<bool>(value) ? "true" : "false");
  else text << boost::any_cast<std::string>(value);
  return text.str();
}

}  // namespace

std::vector<std::pair<std::string, std::string>> configValues(const PlannerConfig& config) {
  std::vector<std::pair<std::string, std::string>> values;
  for (const auto& description : PlannerConfig::__getParamDescriptions__()) {
    boost::any value;
    description->getValue(config, value);
    values.emplace_back(description->name, textOf(description->type, value));
  }
  return values;
}

std::string configValue(const PlannerConfig& config, const std::string& name) {
  for (const auto& [parameter, text] : configValues(config))
    if (parameter == name) return text;
  return "";
}

std::string applyConfig(const PlannerConfig& config, eaci::Parameters& params, RosPlannerOptions& options) {
  for (const auto& [name, text] : configValues(config)) {
    try {
      setRosParameter(params, options, name, text);
    } catch (const eaci::ParameterError& e) {
      return e.what();
    }
  }
  return rosValidationError(params, options);
}

std::string applyConfig(const PlannerConfig& config, const PlannerConfig& previous, eaci::Parameters& params,
                        RosPlannerOptions& options) {
  const auto before = configValues(previous);
  const auto now = configValues(config);
  for (std::size_t i = 0; i < now.size(); ++i) {
    if (i < before.size() && before[i] == now[i]) continue;
    try {
      setRosParameter(params, options, now[i].first, now[i].second);
    } catch (const eaci::ParameterError& e) {
      return e.what();
    }
  }
  return rosValidationError(params, options);
}

void storeInConfig(const eaci::Parameters& params, const RosPlannerOptions& options, PlannerConfig& config) {
  dynamic_reconfigure::Config message;
  for (const auto& description : PlannerConfig::__getParamDescriptions__()) {
    const std::string& name = description->name;
    const std::string text = rosParameterText(params, options, name);
    if (description->type == "int") {
      // The seed is the only one wider than an int (0..2^64-1): one above INT_MAX keeps the
      // config's (parsed without exceptions: stoll throws above 2^63).
      long long value = 0;
      const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
      if (status != std::errc() || end != text.data() + text.size() || value < std::numeric_limits<int>::min() ||
          value > std::numeric_limits<int>::max())
        continue;
      dynamic_reconfigure::IntParameter p;
      p.name = name;
      p.value = static_cast<int>(value);
      message.ints.push_back(p);
    } else if (description->type == "double") {
      dynamic_reconfigure::DoubleParameter p;
      p.name = name;
      p.value = eaci::parseDouble(name, text);
      message.doubles.push_back(p);
    } else if (description->type == "bool") {
      dynamic_reconfigure::BoolParameter p;
      p.name = name;
      p.value = text == "true";
      message.bools.push_back(p);
    } else {
      dynamic_reconfigure::StrParameter p;
      p.name = name;
      p.value = text;
      message.strs.push_back(p);
    }
  }
  config.__fromMessage__(message);
}

}  // namespace eaci_ros
