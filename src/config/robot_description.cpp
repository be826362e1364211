#include "spherical_robots/config/robot_description.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include "spherical_robots/config/urdf_model.hpp"

namespace spherical_robots::config {

double sphereRadiusFromUrdf(const std::string& urdf_xml, const std::string& link) {
  const urdf::ModelInterfaceSharedPtr model = parseUrdf(urdf_xml, "robot description");
  const urdf::LinkConstSharedPtr found = model->getLink(link);
  if (!found) {
    throw std::invalid_argument("robot description '" + model->getName() + "' has no link '" +
                                link + "'");
  }
  urdf::GeometrySharedPtr geometry;
  if (found->collision) {
    geometry = found->collision->geometry;
  } else if (found->visual) {
    geometry = found->visual->geometry;
  }
  if (!geometry || geometry->type != urdf::Geometry::SPHERE) {
    throw std::invalid_argument("robot description: link '" + link +
                                "' needs a sphere collision (or visual) geometry");
  }
  const double radius = std::static_pointer_cast<urdf::Sphere>(geometry)->radius;
  if (!std::isfinite(radius) || radius <= 0.0) {
    std::ostringstream message;
    message << "robot description: link '" << link << "' has sphere radius " << radius
            << ", expected finite and > 0 m";
    throw std::invalid_argument(message.str());
  }
  return radius;
}

std::string readTextFile(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::invalid_argument("cannot read file '" + path + "'");
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string packageShareDirectory() {
  namespace fs = std::filesystem;
  const auto has_config = [](const fs::path& dir) {
    std::error_code ignored;
    return fs::exists(dir / "config" / "terrain.yaml", ignored);
  };
  // Installed layout: <prefix>/lib/spherical_robots/<exe> beside <prefix>/share/spherical_robots.
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    for (const fs::path& candidate :
         {executable.parent_path().parent_path().parent_path() / "share" / "spherical_robots",
          executable.parent_path().parent_path() / "share" / "spherical_robots"}) {
      if (has_config(candidate)) return candidate.string();
    }
  }
  for (const fs::path& candidate :
       {fs::path(SPHERICAL_ROBOTS_INSTALLED_SHARE_DIR), fs::path(SPHERICAL_ROBOTS_SOURCE_DIR)}) {
    if (has_config(candidate)) return candidate.string();
  }
  throw std::invalid_argument(
      std::string("cannot find the spherical_robots share directory (looked beside the "
                  "executable, in " SPHERICAL_ROBOTS_INSTALLED_SHARE_DIR " and in "
                  SPHERICAL_ROBOTS_SOURCE_DIR "); pass --config DIR"));
}

}  // namespace spherical_robots::config
