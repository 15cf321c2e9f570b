#include "asv_planning/param_tree.h"

#include <stdexcept>

namespace asv_planning {

void flattenParams(const XmlRpc::XmlRpcValue& tree, const std::string& prefix, asv::ParamMap& out,
                   const std::string& where) {
  auto& v = const_cast<XmlRpc::XmlRpcValue&>(tree);  // XmlRpcValue's conversions are not const
  switch (v.getType()) {
    case XmlRpc::XmlRpcValue::TypeStruct:
      for (auto it = v.begin(); it != v.end(); ++it)
        flattenParams(it->second, prefix.empty() ? it->first : prefix + "/" + it->first, out, where);
      break;
    case XmlRpc::XmlRpcValue::TypeBoolean:
      out.set(prefix, static_cast<bool>(v) ? "true" : "false");
      break;
    case XmlRpc::XmlRpcValue::TypeInt:
      out.set(prefix, std::to_string(static_cast<int>(v)));
      break;
    case XmlRpc::XmlRpcValue::TypeDouble:
      out.set(prefix, static_cast<double>(v));
      break;
    case XmlRpc::XmlRpcValue::TypeString:
      out.set(prefix, static_cast<std::string>(v));
      break;
    default:
      throw std::invalid_argument(
          "parameter '" + where + prefix +
          "': expected a number, a string, a boolean or a nested mapping (not a list)");
  }
}

}  // namespace asv_planning
