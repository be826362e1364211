#pragma once
// A URDF parsed by urdfdom, its complaints turned into the error.
#include <string>

#include <urdf_model/model.h>
#include <urdf_world/types.h>

namespace spherical_robots::config {

/// The model of urdf_xml. urdfdom reports what it rejects through console_bridge (to standard
/// error) and may still return a model without the rejected element (a sphere with radius "nan"
/// loses its geometry); here every error it reports makes the XML invalid.
/// @param what names the description in the message ("Norma URDF").
/// @throw std::invalid_argument "<what>: not a valid URDF: <urdfdom's errors, in order>".
urdf::ModelInterfaceSharedPtr parseUrdf(const std::string& urdf_xml, const std::string& what);

}  // namespace spherical_robots::config
