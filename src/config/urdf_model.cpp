#include "spherical_robots/config/urdf_model.hpp"

#include <mutex>
#include <stdexcept>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

namespace spherical_robots::config {

namespace {

/// Collects urdfdom's errors instead of printing them, while it is console_bridge's handler.
class CollectErrors final : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char* /*filename*/,
           int /*line*/) override {
    if (level < console_bridge::CONSOLE_BRIDGE_LOG_ERROR) return;
    errors_ += (errors_.empty() ? "" : "; ") + text;
  }
  const std::string& errors() const { return errors_; }

 private:
  std::string errors_;
};

}  // namespace

urdf::ModelInterfaceSharedPtr parseUrdf(const std::string& urdf_xml, const std::string& what) {
  // console_bridge's handler is process-wide.
  static std::mutex handler_mutex;
  const std::lock_guard<std::mutex> lock(handler_mutex);
  CollectErrors collect;
  console_bridge::useOutputHandler(&collect);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(urdf_xml);
  } catch (...) {
    console_bridge::restorePreviousOutputHandler();
    throw;
  }
  console_bridge::restorePreviousOutputHandler();
  if (!model || !collect.errors().empty()) {
    throw std::invalid_argument(what + ": not a valid URDF: " +
                                (collect.errors().empty() ? "urdfdom returned no model"
                                                          : collect.errors()));
  }
  return model;
}

}  // namespace spherical_robots::config
