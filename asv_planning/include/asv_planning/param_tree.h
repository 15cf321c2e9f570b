// A ROS parameter tree (nested structs of scalars, as rosparam loads a YAML mapping) as an asv::ParamMap
// with "a/b" keys and text values: how the nodes hand their YAML sub-trees to the ROS-free core.
#pragma once

#include <string>

#include <asv_core/common/param_map.h>
#include <xmlrpcpp/XmlRpcValue.h>

namespace asv_planning {

// Adds every scalar of `tree` under `prefix` to `out`. A list (or any other non-scalar leaf) throws
// std::invalid_argument naming `where` + its key.
void flattenParams(const XmlRpc::XmlRpcValue& tree, const std::string& prefix, asv::ParamMap& out,
                   const std::string& where = "");

}  // namespace asv_planning
