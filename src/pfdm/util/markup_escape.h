// Text made safe inside XML and HTML markup, attributes included.
#ifndef PFDM_UTIL_MARKUP_ESCAPE_H_
#define PFDM_UTIL_MARKUP_ESCAPE_H_

#include <string>

namespace pfdm {

// text with & < > " escaped.
std::string EscapeMarkup(const std::string& text);

}  // namespace pfdm

#endif  // PFDM_UTIL_MARKUP_ESCAPE_H_
