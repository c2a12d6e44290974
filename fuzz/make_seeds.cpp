// Writes the seed corpora of the fuzzers from the reference cases, so that no request is copied
// into code: every case's `request` of <reference dir>/*.json becomes one file
// <out dir>/<slug>/<case id>.json, the slug being the case file's endpoint without "/v1/" and
// with '/' and '-' as '_' ("/v1/roughness/groove-wall" -> roughness_groove_wall; the fuzzer
// <slug>_fuzzer and <slug>_text_fuzzer read it). Also writes <out dir>/reference_keys.dict: the
// keys and string values of the requests as libFuzzer dictionary entries.
//
// The byte-level engine fuzzer (http_engine_fuzzer) gets <out dir>/http_engine/: each reference
// request as a whole HTTP/1.1 request (Content-Length; every third one chunked, every fifth with
// Expect: 100-continue) followed by a pipelined GET, plus a few fixed exchanges (pipelines, HEAD,
// OPTIONS, the request-smuggling shapes). Each seed's first byte chooses the piece sizes.
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

// One request as the engine fuzzer sends it; `form` 0: Content-Length, 1: chunked in two chunks,
// 2: Content-Length with Expect: 100-continue.
std::string http_request(const std::string& endpoint, const std::string& body, int form) {
  std::string request =
      "POST " + endpoint + " HTTP/1.1\r\nHost: cutcalc\r\n" + "Content-Type: application/json\r\n";
  if (form == 1) {
    const std::size_t half = body.size() / 2;
    char sizes[2][32];
    std::snprintf(sizes[0], sizeof sizes[0], "%zx", half);
    std::snprintf(sizes[1], sizeof sizes[1], "%zx", body.size() - half);
    return request + "Transfer-Encoding: chunked\r\n\r\n" + sizes[0] + "\r\n" +
           body.substr(0, half) + "\r\n" + sizes[1] + "\r\n" + body.substr(half) + "\r\n0\r\n\r\n";
  }
  if (form == 2) request += "Expect: 100-continue\r\n";
  return request + "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}

void write_engine_seed(const fs::path& corpus, const std::string& name, char chooser,
                       const std::string& bytes) {
  std::ofstream(corpus / name, std::ios::binary) << chooser << bytes;
}

// Exchanges that no reference case gives: pipelines of the operational endpoints, HEAD, a CORS
// preflight, and the framing shapes a proxy could disagree on (each must be answered once).
void write_fixed_engine_seeds(const fs::path& corpus) {
  const std::string get = "GET /healthz HTTP/1.1\r\nHost: cutcalc\r\n\r\n";
  std::string pipeline;
  for (int i = 0; i < 8; ++i) pipeline += get;
  write_engine_seed(corpus, "pipeline-8", 0, pipeline);
  write_engine_seed(corpus, "pipeline-8-pieces", 3, pipeline);
  write_engine_seed(corpus, "operational", 0,
                    "GET /version HTTP/1.1\r\nHost: a\r\n\r\nHEAD /readyz HTTP/1.1\r\nHost: a"
                    "\r\n\r\nGET /metrics HTTP/1.0\r\nConnection: Keep-Alive\r\n\r\n"
                    "GET /nope HTTP/1.1\r\nHost: a\r\n\r\n");
  write_engine_seed(corpus, "preflight", 0,
                    "OPTIONS /v1/entry-length HTTP/1.1\r\nHost: a\r\nOrigin: https://x\r\n"
                    "Access-Control-Request-Method: POST\r\n\r\n");
  write_engine_seed(corpus, "cl-and-te", 0,
                    "POST /v1/main-time HTTP/1.1\r\nHost: a\r\nContent-Length: 5\r\n"
                    "Transfer-Encoding: chunked\r\n\r\n0\r\n\r\n" +
                        get);
  write_engine_seed(corpus, "two-lengths", 0,
                    "POST /v1/main-time HTTP/1.1\r\nHost: a\r\nContent-Length: 2\r\n"
                    "Content-Length: 3\r\n\r\n{}\r\n" +
                        get);
  write_engine_seed(corpus, "body-after-405", 0,
                    "DELETE /v1/roughness/bore-milling HTTP/1.1\r\nHost: a\r\nContent-Length: " +
                        std::to_string(get.size()) + "\r\n\r\n" + get + get);
  write_engine_seed(corpus, "expect-too-large", 0,
                    "POST /v1/entry-length HTTP/1.1\r\nHost: a\r\nExpect: 100-continue\r\n"
                    "Content-Length: 100000000\r\n\r\n");
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
    std::size_t engine_seeds = 0;
    const fs::path engine_corpus = out_dir / "http_engine";
    fs::create_directories(engine_corpus);
    write_fixed_engine_seeds(engine_corpus);
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
        // Every third chunked, every fifth (of the rest) with Expect: 100-continue.
        const int form = engine_seeds % 3 == 1 ? 1 : engine_seeds % 5 == 2 ? 2 : 0;
        const char chooser = static_cast<char>(engine_seeds % 4 == 0 ? 0 : engine_seeds % 13 + 1);
        write_engine_seed(
            engine_corpus, name, chooser,
            http_request(reference.at("endpoint").get<std::string>(), request.dump(), form) +
                "GET /healthz HTTP/1.1\r\nHost: cutcalc\r\n\r\n");
        ++engine_seeds;
        // The same request asking for the web calculator's plot data, so that the fuzzers start
        // inside those code paths too.
        if (const auto plot = plot_request(reference.at("endpoint").get<std::string>(), request)) {
          std::ofstream(corpus / ("plot-" + name)) << plot->dump();
          ++seeds;
        }
        // Polygon programs in another dialect and unit (programs.md section 2), so that the
        // fuzzers start inside the dialect writers too.
        if (reference.at("endpoint") == "/v1/polygon-hole/gcode" && request.is_object()) {
          nlohmann::json dialect = request;
          dialect.erase("safe_z_mm");
          dialect["program"] = {{"dialect", seeds % 2 == 0 ? "fanuc" : "sinumerik"},
                                {"units", "inch"},
                                {"name", "HOLE_1"},
                                {"tool_number", 2},
                                {"tool_length_offset", true},
                                {"coolant", "mist"}};
          dialect["machine"] = {{"max_spindle_rpm", 100}, {"max_feed_mm_per_min", 1000}};
          std::ofstream(corpus / ("program-" + name)) << dialect.dump();
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
    std::printf(
        "seeds: %zu requests (%zu HTTP exchanges) from %zu reference files, %zu dictionary"
        " tokens\n",
        seeds, engine_seeds, files, tokens.size());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "cutcalc_fuzz_seeds: %s\n", error.what());
    return 1;
  }
  return 0;
}
