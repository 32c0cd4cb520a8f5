// Base64 (RFC 4648, with padding): the PNG pictures a report embeds as data: URLs.
#pragma once

#include <string>
#include <string_view>

namespace sonarcarve {

std::string base64(std::string_view bytes);

}  // namespace sonarcarve
