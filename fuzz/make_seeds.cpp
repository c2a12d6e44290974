// Writes what the fuzz run needs from the route table (api/routes.cpp), the reference cases and
// openapi.yaml, so that no request, path or field name is copied into fuzz/:
//  - <out dir>/harnesses.txt: one line "<harness> <path> <form>" per route and answer form, the
//    harness named <slug>_fuzzer or <slug>_text_fuzzer (api::route_slug); scripts/ci-fuzz.sh runs
//    endpoint_fuzzer once per line;
//  - <out dir>/<slug>/<index>_<case id>.json: every case's `request` of the reference files
//    (<reference dir>/*.json plus the next/ files the routes list), plus the same request asking
//    for the route's plot data (its plot field), for the polygon program, other dialects, and
//    for the pass program, the main-time requests with pass_split or finish;
//  - <out dir>/tokens.dict: libFuzzer dictionary entries: the keys and string values of the
//    requests, every property name and string enum/const of openapi.yaml, each plot field with
//    its example value;
//  - <out dir>/paths.dict: the calculation paths, for the engine fuzzer's dictionary.
//
// The G-code reader fuzzer (gcode_reader_fuzzer) gets <out dir>/gcode_reader/: the programs the
// program routes write for their first reference requests that answer 200, in each dialect the
// route accepts (cut at a line end within the run's 4096-byte inputs), and a few hand-written
// programs with what cutcalc never writes (arcs in every plane, R and turns, inch, lathe words,
// refusals).
//
// The byte-level engine fuzzer (http_engine_fuzzer) gets <out dir>/http_engine/: each reference
// request as a whole HTTP/1.1 request (Content-Length; every third one chunked, every fifth with
// Expect: 100-continue) followed by a pipelined GET, plus a few fixed exchanges (pipelines, HEAD,
// OPTIONS, the request-smuggling shapes). Each seed's first byte chooses the piece sizes.
//
// Usage: cutcalc_fuzz_seeds <reference dir> <openapi.yaml> <out dir>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <nlohmann/json.hpp>

#include "api/routes.h"

namespace {

namespace fs = std::filesystem;

// The request with the route's opt-in plot field set (and the member it cannot be combined with
// dropped), when the route has one.
std::optional<nlohmann::json> plot_request(const cutcalc::api::CalculationRoute& route,
                                           const nlohmann::json& request) {
  if (!request.is_object() || route.plot.name.empty()) {
    return std::nullopt;
  }
  nlohmann::json plot = request;
  if (!route.plot.replaces.empty()) {
    plot.erase(std::string(route.plot.replaces));
  }
  plot[std::string(route.plot.name)] = nlohmann::json::parse(route.plot.example);
  return plot;
}

// reference/*.json plus the next/ files the routes list (api/routes.h).
std::vector<fs::path> reference_files(const fs::path& reference_dir) {
  std::set<fs::path> files;
  for (const auto& entry : fs::directory_iterator(reference_dir)) {
    if (entry.path().extension() == ".json") {
      files.insert(entry.path());
    }
  }
  for (const cutcalc::api::CalculationRoute& route : cutcalc::api::calculation_routes()) {
    for (const std::string_view file : cutcalc::api::reference_files_of(route)) {
      if (file.starts_with("next/")) {
        files.insert(reference_dir / file);
      }
    }
  }
  return {files.begin(), files.end()};
}

// The property names and string enum and const values of an openapi.yaml node, as JSON strings.
void collect_openapi_tokens(const YAML::Node& node, std::set<std::string>& tokens) {
  if (node.IsMap()) {
    for (const auto& member : node) {
      const std::string key = member.first.as<std::string>();
      if (key == "properties" && member.second.IsMap()) {
        for (const auto& property : member.second) {
          tokens.insert(nlohmann::json(property.first.as<std::string>()).dump());
        }
      } else if ((key == "enum" && member.second.IsSequence()) ||
                 (key == "const" && member.second.IsScalar())) {
        for (const YAML::Node& value :
             member.second.IsSequence()
                 ? std::vector<YAML::Node>(member.second.begin(), member.second.end())
                 : std::vector<YAML::Node>{member.second}) {
          if (value.IsScalar()) {
            tokens.insert(nlohmann::json(value.as<std::string>()).dump());
          }
        }
      }
      collect_openapi_tokens(member.second, tokens);
    }
  } else if (node.IsSequence()) {
    for (const YAML::Node& element : node) {
      collect_openapi_tokens(element, tokens);
    }
  }
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

// Programs with the words cutcalc's own programs lack (machine-time.md section 4).
void write_fixed_program_seeds(const fs::path& corpus) {
  static const std::vector<std::pair<std::string, std::string>> kPrograms = {
      {"arcs-linuxcnc.ngc",
       "%\n(ARCS)\nG21 G90 G17 G64 P0.01\nG0 X10 Y0 Z1\nF600\nG3 X0 Y10 I-10 J0\n"
       "G2 X10 Y0 R-10\nG3 X10 Y0 Z-3 I-10 J0 P3\nG18 G2 X0 Z-3 I-5 K0\nG19 G3 Y5 Z5 R5\n"
       "G90.1 G17 G2 X10 Y5 I5 J5\nG91.1 G61.1 G1 X20 A90\nG61 G4 P0.5\nT2 M6\nM0\nM2\n%\n"},
      {"lathe-linuxcnc.ngc",
       "%\nG20 G18 G7 G90 G95\nG96 D2500 S600 M3\nG0 X2 Z0.1\nG1 X1.5 F0.004\n"
       "G2 X1.8 Z-0.2 R0.2\nG97 S1000\nG8 G91 G1 X-0.1 Z-0.1\nM5\nM30\n%\n"},
      {"lathe-fanuc.nc",
       "%\nO0100 (TURN)\nG21\nG18 G40 G99\nG54\nT0303\nG00 X50. Z2.\nG50 S2000\n"
       "G96 S180 M03\nG01 U-4. F0.2\nW-10.\nG02 X50. Z-15. R5.\nG04 X0.5\nG98 G01 Z5. F500.\n"
       "M05\nM30\n%\n"},
      {"mill-fanuc.nc",
       "%\nO0001 (POCKET)\nG20\nG17 G40 G49 G80 G90 G94\nG54.1 P2\nT1 M06\n"
       "G00 G43 Z0.5 H1\nS8000 M03\nG61 G01 Z-0.1 F20.\nG09 X1.\nG64 G03 X0 Y1. I-1. J0\n"
       "G91 G01 X-1.\nG92 X0 Y0\nG04 P250\nM30\n%\n"},
      {"turn-sinumerik.mpf",
       "; TURN\nG18 G710 G40 G90 G95 DIAMON\nG54\nT=\"FINISH\" D1\nG0 X52 Z2\n"
       "G96 S200 LIMS=3000 M3\nG1 X40 F0.15\nG2 X50 Z-5 CR=5\nDIAM90\nG4 F0.5\nG97 S800\n"
       "G4 S2\nM5\nM30\n"},
      {"mill-sinumerik.mpf",
       "; MILL\nG17 G700 G40 G90 G94\nG500\nT3\nM6\nD1\nG0 Z0.5\nS6000 M3\n"
       "G641 ADIS=0.002 G1 Z-0.1 F10\nG60 G2 X1 Y1 I0.5 J0.5 TURN=1\nG9 G64 G1 X0\nMSG(\"DONE\")\n"
       "G93 G1 X1 F2\nM30\n"},
      {"refusals.ngc",
       "G21\n#1=5\nG1 X[1+#1] F100\no100 call\nG41 D1\nG81 Z-1 R1\nG28\nG64 Q0.1\n"
       "G1 X1\nG95 G1 X2 F0.1\nG2 X3 Y0 R0.1\nM98 P10\n"},
  };
  for (const auto& [name, text] : kPrograms) {
    std::ofstream(corpus / name) << text;
  }
}

// The programs of one route for one reference request, in each dialect it accepts.
std::size_t write_program_seeds(const cutcalc::api::CalculationRoute& route,
                                const nlohmann::json& request, const std::string& name,
                                const fs::path& corpus) {
  std::size_t written = 0;
  for (const char* dialect : {"linuxcnc", "fanuc", "sinumerik"}) {
    nlohmann::json variant = request;
    if (!variant.contains("program")) variant["program"] = nlohmann::json::object();
    variant["program"]["dialect"] = dialect;
    if (std::string_view(dialect) != "fanuc") variant["program"].erase("program_number");
    cutcalc::api::HandlerOutcome outcome = route.handler(variant);
    auto* both = std::get_if<cutcalc::api::JsonWithText>(&outcome);
    if (both != nullptr) cutcalc::api::write_whole(*both);
    if (both == nullptr) continue;  // the route refuses this dialect
    std::string program = both->text;
    constexpr std::size_t kMaxLen = 4096;  // scripts/ci-fuzz.sh -max_len
    if (program.size() > kMaxLen) program.erase(program.rfind('\n', kMaxLen - 1) + 1);
    std::ofstream(corpus / (std::string(dialect) + "-" + name + ".nc")) << program;
    ++written;
  }
  return written;
}

}  // namespace

int main(int argc, char** argv) {
  using cutcalc::api::CalculationRoute;
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s <reference dir> <openapi.yaml> <out dir>\n", argv[0]);
    return 2;
  }
  try {
    const fs::path reference_dir = argv[1];
    const fs::path out_dir = argv[3];
    std::set<std::string> tokens;
    collect_openapi_tokens(YAML::LoadFile(argv[2]), tokens);
    std::size_t files = 0;
    std::size_t seeds = 0;
    std::size_t engine_seeds = 0;
    const fs::path engine_corpus = out_dir / "http_engine";
    fs::create_directories(engine_corpus);
    write_fixed_engine_seeds(engine_corpus);
    const fs::path gcode_corpus = out_dir / "gcode_reader";
    fs::create_directories(gcode_corpus);
    write_fixed_program_seeds(gcode_corpus);
    std::size_t program_seeds = 0;
    std::ofstream harnesses(out_dir / "harnesses.txt");
    std::ofstream paths(out_dir / "paths.dict");
    for (const CalculationRoute& route : cutcalc::api::calculation_routes()) {
      const std::string slug = cutcalc::api::route_slug(route.path);
      harnesses << slug << "_fuzzer " << route.path << " json\n";
      if (route.forms == cutcalc::api::AnswerForms::json_and_plain_text_program) {
        harnesses << slug << "_text_fuzzer " << route.path << " plain_text\n";
      }
      paths << dict_entry(route.path) << '\n';
      if (!route.plot.name.empty()) {
        tokens.insert('"' + std::string(route.plot.name) + "\":" + std::string(route.plot.example));
      }
      fs::create_directories(out_dir / slug);
    }
    for (const fs::path& file : reference_files(reference_dir)) {
      std::ifstream in(file);
      const nlohmann::json reference = nlohmann::json::parse(in);
      const std::string endpoint = reference.at("endpoint").get<std::string>();
      const CalculationRoute* route = cutcalc::api::find_calculation_route(endpoint);
      if (route == nullptr) {
        std::fprintf(stderr, "cutcalc_fuzz_seeds: %s: %s is no route, skipped\n", file.c_str(),
                     endpoint.c_str());
        continue;
      }
      const fs::path corpus = out_dir / cutcalc::api::route_slug(endpoint);
      const std::string prefix = file.parent_path().filename() == "next" ? "next-" : "";
      std::size_t index = 0;
      std::size_t program_cases = 0;
      for (const auto& reference_case : reference.at("cases")) {
        const nlohmann::json& request = reference_case.at("request");
        const std::string name = prefix + file_name_of(reference_case.value("id", ""), index++);
        std::ofstream(corpus / name) << request.dump();
        // The first three answered requests of a program route seed the G-code reader.
        if (route->forms == cutcalc::api::AnswerForms::json_and_plain_text_program &&
            program_cases < 3 && reference_case.at("expect").value("status", 0) == 200) {
          program_seeds +=
              write_program_seeds(*route, request, fs::path(name).stem().string(), gcode_corpus);
          ++program_cases;
        }
        collect_tokens(request, tokens);
        ++seeds;
        // Every third chunked, every fifth (of the rest) with Expect: 100-continue.
        const int form = engine_seeds % 3 == 1 ? 1 : engine_seeds % 5 == 2 ? 2 : 0;
        const char chooser = static_cast<char>(engine_seeds % 4 == 0 ? 0 : engine_seeds % 13 + 1);
        write_engine_seed(engine_corpus, name, chooser,
                          http_request(endpoint, request.dump(), form) +
                              "GET /healthz HTTP/1.1\r\nHost: cutcalc\r\n\r\n");
        ++engine_seeds;
        // The same request asking for the web calculator's plot data, so that the fuzzers start
        // inside those code paths too.
        if (const auto plot = plot_request(*route, request)) {
          std::ofstream(corpus / ("plot-" + name)) << plot->dump();
          ++seeds;
        }
        // Polygon programs in another dialect and unit (programs.md section 2), so that the
        // fuzzers start inside the dialect writers too.
        if (endpoint == "/v1/polygon-hole/gcode" && request.is_object()) {
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
        // Main-time requests with equal passes or a finishing level (entry-and-main-time.md
        // section 15) also seed the pass program, which takes the same fields and has no such
        // reference case of its own.
        if (endpoint == "/v1/main-time" && request.is_object() &&
            (request.contains("pass_split") || request.contains("finish"))) {
          nlohmann::json program = request;
          program.erase("extra_path_mm");
          program["program"] = {{"dialect", seeds % 2 == 0 ? "fanuc" : "sinumerik"},
                                {"units", "inch"}};
          const fs::path program_corpus =
              out_dir / cutcalc::api::route_slug("/v1/main-time/program");
          std::ofstream(program_corpus / ("main-time-" + name)) << program.dump();
          ++seeds;
        }
      }
      ++files;
    }
    if (seeds == 0) {
      std::fprintf(stderr, "no reference cases found in %s\n", reference_dir.c_str());
      return 1;
    }
    std::ofstream dict(out_dir / "tokens.dict");
    for (const std::string& token : tokens) {
      dict << dict_entry(token) << '\n';
    }
    std::printf(
        "seeds: %zu requests (%zu HTTP exchanges, %zu programs) from %zu reference files for %zu"
        " routes, %zu dictionary tokens\n",
        seeds, engine_seeds, program_seeds, files, cutcalc::api::calculation_routes().size(),
        tokens.size());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "cutcalc_fuzz_seeds: %s\n", error.what());
    return 1;
  }
  return 0;
}
