#include "service/httplib_adapter.h"

#include <httplib.h>

namespace cutcalc::service {

std::string percent_decode_path(std::string_view path) {
  return httplib::detail::decode_url(std::string(path), false);
}

}  // namespace cutcalc::service
