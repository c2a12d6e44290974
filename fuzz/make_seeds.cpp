// Writes the seed corpora of the fuzzers from the reference cases, so that no request is copied
// into code: every case's `request` of <reference dir>/*.json becomes one file
// <out dir>/<slug>/<case id>.json, the slug being the case file's endpoint without "/v1/" and
// with '/' and '-' as '_' ("/v1/roughness/groove-wall" -> roughness_groove_wall; the fuzzer
// <slug>_fuzzer and <slug>_text_fuzzer read it). Also writes <out dir>/reference_keys.dict: the
// keys and string values of the requests as libFuzzer dictionary entries.
//
// Usage: cutcalc_fuzz_seeds <reference dir> <out dir>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

// The request with the opt-in plot field of its endpoint set, when the endpoint has one and the
// request does not already choose its points.
std::optional<nlohmann::json> plot_request(const std::string& endpoint,
                                           const nlohmann::json& request) {
  if (!request.is_object()) {
    return std::nullopt;
  }
  nlohmann::json plot = request;
  if (endpoint == "/v1/entry-length") {
    plot["include_scheme"] = true;
  } else if (endpoint == "/v1/resultant-speeds" && !request.contains("contact_angles_deg")) {
    plot["arc_samples"] = 91;
  } else if (endpoint == "/v1/roughness/groove-wall") {
    plot["curve_points"] = 121;
  } else if (endpoint == "/v1/polygon-hole/gcode") {
    plot["include_geometry"] = true;
  } else {
    return std::nullopt;
  }
  return plot;
}

std::string slug_of(std::string endpoint) {
  if (endpoint.rfind("/v1/", 0) == 0) {
    endpoint.erase(0, 4);
  }
  for (char& c : endpoint) {
    if (c == '/' || c == '-') {
      c = '_';
    }
  }
  return endpoint;
}

std::string file_name_of(const std::string& id, std::size_t index) {
  std::string name = std::to_string(index) + "_";
  for (const char c : id) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    name += plain ? c : '_';
  }
  return name + ".json";
}

void collect_tokens(const nlohmann::json& value, std::set<std::string>& tokens) {
  if (value.is_object()) {
    for (const auto& [key, element] : value.items()) {
      tokens.insert(nlohmann::json(key).dump());
      collect_tokens(element, tokens);
    }
  } else if (value.is_array()) {
    for (const auto& element : value) {
      collect_tokens(element, tokens);
    }
  } else if (value.is_string()) {
    tokens.insert(value.dump());
  }
}

// A libFuzzer dictionary value: "..." with \\, \" and \xNN escapes.
std::string dict_entry(const std::string& token) {
  std::string out = "\"";
  for (const char c : token) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (byte < 0x20 || byte > 0x7e) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", byte);
      out += hex;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s <reference dir> <out dir>\n", argv[0]);
    return 2;
  }
  try {
    const fs::path reference_dir = argv[1];
    const fs::path out_dir = argv[2];
    std::set<std::string> tokens;
    std::size_t files = 0;
    std::size_t seeds = 0;
    for (const auto& entry : fs::directory_iterator(reference_dir)) {
      if (entry.path().extension() != ".json") {
        continue;
      }
      std::ifstream in(entry.path());
      const nlohmann::json reference = nlohmann::json::parse(in);
      const fs::path corpus = out_dir / slug_of(reference.at("endpoint").get<std::string>());
      fs::create_directories(corpus);
      std::size_t index = 0;
      for (const auto& reference_case : reference.at("cases")) {
        const nlohmann::json& request = reference_case.at("request");
        const std::string name = file_name_of(reference_case.value("id", ""), index++);
        std::ofstream(corpus / name) << request.dump();
        collect_tokens(request, tokens);
        ++seeds;
        // The same request asking for the web calculator's plot data, so that the fuzzers start
        // inside those code paths too.
        if (const auto plot = plot_request(reference.at("endpoint").get<std::string>(), request)) {
          std::ofstream(corpus / ("plot-" + name)) << plot->dump();
          ++seeds;
        }
      }
      ++files;
    }
    if (seeds == 0) {
      std::fprintf(stderr, "no reference cases found in %s\n", reference_dir.c_str());
      return 1;
    }
    std::ofstream dict(out_dir / "reference_keys.dict");
    for (const std::string& token : tokens) {
      dict << dict_entry(token) << '\n';
    }
    std::printf("seeds: %zu requests from %zu reference files, %zu dictionary tokens\n", seeds,
                files, tokens.size());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "cutcalc_fuzz_seeds: %s\n", error.what());
    return 1;
  }
  return 0;
}
