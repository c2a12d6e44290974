#include "api/accept_header.h"

#include <algorithm>
#include <charconv>
#include <optional>
#include <string>

#include "domain/common/ascii_text.h"

namespace cutcalc::api {
namespace {

// The q value of one media range ("text/plain;q=0.5"); 1 when absent, 0 when malformed.
double quality(std::string_view parameters) {
  while (!parameters.empty()) {
    const auto semicolon = parameters.find(';');
    const std::string_view parameter = domain::trim_space(parameters.substr(0, semicolon));
    parameters =
        semicolon == std::string_view::npos ? std::string_view{} : parameters.substr(semicolon + 1);
    if (parameter.size() > 2 && (parameter[0] == 'q' || parameter[0] == 'Q') &&
        parameter[1] == '=') {
      double q = 0.0;
      const std::string_view value = parameter.substr(2);
      const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), q);
      if (error != std::errc() || end != value.data() + value.size() || q < 0.0 || q > 1.0) {
        return 0.0;
      }
      return q;
    }
  }
  return 1.0;
}

// The highest q the header gives to exactly `media_type`, or nullopt when it is not named.
std::optional<double> named_quality(std::string_view accept, std::string_view media_type) {
  std::optional<double> best;
  while (!accept.empty()) {
    const auto comma = accept.find(',');
    const std::string_view range = accept.substr(0, comma);
    accept = comma == std::string_view::npos ? std::string_view{} : accept.substr(comma + 1);
    const auto semicolon = range.find(';');
    if (domain::iequals_ascii(domain::trim_space(range.substr(0, semicolon)), media_type)) {
      const double q =
          semicolon == std::string_view::npos ? 1.0 : quality(range.substr(semicolon + 1));
      best = std::max(best.value_or(0.0), q);
    }
  }
  return best;
}

struct LanguageRank {
  double q = 0.0;
  std::size_t position = 0;  // of the first range naming the language: earlier wins a tie
};

// The highest q the header gives to a range naming `language` ("ru" or "ru-..."); q 0 when none.
LanguageRank language_rank(std::string_view header, std::string_view language) {
  LanguageRank rank;
  bool named = false;
  for (std::size_t position = 0; !header.empty(); ++position) {
    const auto comma = header.find(',');
    const std::string_view range = header.substr(0, comma);
    header = comma == std::string_view::npos ? std::string_view{} : header.substr(comma + 1);
    const auto semicolon = range.find(';');
    const std::string_view tag = domain::trim_space(range.substr(0, semicolon));
    const bool names = domain::iequals_ascii(tag, language) ||
                       (tag.size() > language.size() && tag[language.size()] == '-' &&
                        domain::iequals_ascii(tag.substr(0, language.size()), language));
    if (names) {
      const double q =
          semicolon == std::string_view::npos ? 1.0 : quality(range.substr(semicolon + 1));
      if (!named) rank.position = position;
      named = true;
      rank.q = std::max(rank.q, q);
    }
  }
  return rank;
}

}  // namespace

Language preferred_language(std::string_view accept_language) {
  const LanguageRank russian = language_rank(accept_language, "ru");
  const LanguageRank english = language_rank(accept_language, "en");
  const bool russian_first =
      russian.q > english.q || (russian.q == english.q && russian.position < english.position);
  return russian.q > 0.0 && russian_first ? Language::ru : Language::en;
}

bool prefers_plain_text(std::string_view accept) {
  const auto text = named_quality(accept, "text/plain");
  if (!text || *text <= 0.0) {
    return false;
  }
  const auto json = named_quality(accept, "application/json");
  return !json || *text > *json;
}

}  // namespace cutcalc::api
