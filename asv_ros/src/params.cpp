#include "asv_ros/params.h"

#include <xmlrpcpp/XmlRpcValue.h>

namespace asv_ros {

namespace {

std::string scalarText(XmlRpc::XmlRpcValue& v, asv::ParamType& type) {
  switch (v.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      type = asv::ParamType::Bool;
      return static_cast<bool>(v) ? "true" : "false";
    case XmlRpc::XmlRpcValue::TypeInt:
      type = asv::ParamType::Int;
      return std::to_string(static_cast<int>(v));
    case XmlRpc::XmlRpcValue::TypeDouble: {
      asv::ParamMap m;  // the map's own text form of a double (17 significant digits)
      m.set("x", static_cast<double>(v));
      type = asv::ParamType::Double;
      return m.values().at("x");
    }
    case XmlRpc::XmlRpcValue::TypeString:
      type = asv::ParamType::String;
      return static_cast<std::string>(v);
    default:
      return {};
  }
}

void flatten(XmlRpc::XmlRpcValue& v, const std::string& key, asv::ParamMap& out) {
  auto bad = [&] {
    return std::invalid_argument("parameter '" + out.fullName(key) +
                                 "': expected a number, a string, a boolean, a list of those or a mapping");
  };
  asv::ParamType type = asv::ParamType::Text;
  if (v.getType() == XmlRpc::XmlRpcValue::TypeStruct) {
    for (auto it = v.begin(); it != v.end(); ++it)
      flatten(it->second, key.empty() ? it->first : key + "/" + it->first, out);
  } else if (v.getType() == XmlRpc::XmlRpcValue::TypeArray) {
    std::vector<std::string> items;
    for (int i = 0; i < v.size(); ++i) {
      items.push_back(scalarText(v[i], type));
      if (type == asv::ParamType::Text)
        throw bad();
    }
    out.setList(key, items);
  } else {
    const std::string text = scalarText(v, type);
    if (type == asv::ParamType::Text)
      throw bad();
    out.set(key, text, type);
  }
}

}  // namespace

asv::ParamMap readParams(const ros::NodeHandle& nh) {
  asv::ParamMap out;
  out.setLabel(nh.getNamespace() + "/");
  XmlRpc::XmlRpcValue tree;
  if (!ros::param::has(nh.getNamespace()))
    return out;
  if (!ros::param::get(nh.getNamespace(), tree))
    throw std::runtime_error("cannot read the parameters under " + nh.getNamespace() +
                             " (is the master running?)");
  if (tree.getType() != XmlRpc::XmlRpcValue::TypeStruct)
    throw std::invalid_argument("parameter '" + nh.getNamespace() + "' must be a namespace, not a value");
  flatten(tree, "", out);
  return out;
}

void rejectUnknown(const asv::ParamMap& params, const std::string& yaml,
                   const std::vector<std::string>& subtrees) {
  const std::vector<std::string> unknown = params.unknownKeys(subtrees);
  if (!unknown.empty())
    throw std::invalid_argument("unknown parameter '" + params.fullName(unknown.front()) + "' (typo? see " +
                                yaml + " for the keys)");
}

void rejectTypoBehindError(const asv::ParamMap& params, const std::string& yaml,
                           const std::vector<std::string>& subtrees) {
  if (!params.readFailed())
    rejectUnknown(params, yaml, subtrees);
}

}  // namespace asv_ros
