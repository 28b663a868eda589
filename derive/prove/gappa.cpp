#include "prove/gappa.hpp"

#include "core/output_files.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

namespace billiards::derive {

std::string gappa_rounding(int digits, int min_exponent) {
  if (digits == 24 && min_exponent == -125) return "float<ieee_32, ne>";
  if (digits == 53 && min_exponent == -1021) return "float<ieee_64, ne>";
  return "float<" + std::to_string(digits) + ", " + std::to_string(min_exponent - digits) + ", ne>";
}

bool gappa_proved(int status, const std::string& output) {
  return status == 0 && output.find("not satisfied") == std::string::npos &&
         output.find("Error") == std::string::npos;
}

std::string gappa_failure(const std::string& output) {
  std::size_t at = output.find("not satisfied:");
  if (at != std::string::npos) {
    at = output.find_first_not_of(" \n", at + 14);
  } else {
    at = output.find("Error");
  }
  if (at == std::string::npos) return output;
  return output.substr(at, output.find('\n', at) - at);
}

std::string only_what_is_read(const std::string& script) {
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < script.size();) {
    const std::size_t end = script.find('\n', at);
    lines.push_back(script.substr(at, end == std::string::npos ? std::string::npos : end - at));
    at = end == std::string::npos ? script.size() : end + 1;
  }
  const auto defined = [](const std::string& line) -> std::string {
    const std::size_t space = line.find(' ');
    if (space == std::string::npos || line.empty() || line[0] == '@' || line[0] == '{') return "";
    const std::string rest = line.substr(space + 1);
    return rest.rfind("= ", 0) == 0 || rest.rfind("rnd= ", 0) == 0 ? line.substr(0, space) : "";
  };
  std::set<std::string> read;
  const auto reads = [&](const std::string& text) {
    for (std::size_t at = 0; at < text.size();) {
      if (std::isalpha(static_cast<unsigned char>(text[at])) || text[at] == '_') {
        std::size_t end = at;
        while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_'))
          ++end;
        read.insert(text.substr(at, end - at));
        at = end;
      } else {
        ++at;
      }
    }
  };
  std::vector<bool> kept(lines.size(), false);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (defined(lines[i]).empty()) {
      kept[i] = true;
      reads(lines[i]);
    }
  }
  for (std::size_t i = lines.size(); i-- > 0;) {
    const std::string name = defined(lines[i]);
    if (name.empty() || !read.count(name)) continue;
    kept[i] = true;
    reads(lines[i].substr(name.size()));
  }
  std::string out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (kept[i]) out += lines[i] + "\n";
  }
  return out;
}

namespace {

constexpr int not_run = -2;

// What a command printed (stdout and stderr) and its exit status: −1 where it did not exit (a signal),
// not_run where it could not be started or waited for.
std::pair<int, std::string> run_command(const std::string& command) {
  std::string output;
  int status = -1;
  if (FILE* pipe = popen((command + " 2>&1").c_str(), "r")) {
    char buffer[4096];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, n);
    status = pclose(pipe);
  }
  if (status == -1) return {not_run, output};
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

}  // namespace

ProofCache::ProofCache(std::filesystem::path folder, std::string version)
    : folder_(std::move(folder)), version_(std::move(version)) {
  if (version_.empty()) folder_.clear();  // no version to key the answers by: no cache
}

ProofCache& ProofCache::instance() {
  static ProofCache cache = [] {
    const char* folder = std::getenv("BILLIARDS_PROOF_CACHE");
    if (folder == nullptr || *folder == '\0') return ProofCache({}, "");
    const auto [status, version] = run_command("gappa --version");
    if (status != 0) return ProofCache({}, "");
    return ProofCache(folder, version);
  }();
  return cache;
}

std::optional<std::pair<int, std::string>> ProofCache::find(const std::string& script) const {
  if (folder_.empty()) return std::nullopt;
  std::ifstream file(path(script), std::ios::binary);
  if (!file) return std::nullopt;
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  // The entry as this run would write it, up to Gappa's output: the header, version, script and status.
  for (const int status : {0, 1}) {
    const std::string expected = entry(script, status, "");
    const std::size_t fixed = expected.size() - 1;  // less the output's closing newline
    if (text.size() > fixed && text.compare(0, fixed, expected, 0, fixed) == 0 && text.back() == '\n')
      return std::pair<int, std::string>{status, text.substr(fixed, text.size() - fixed - 1)};
  }
  return std::nullopt;
}

void ProofCache::keep(const std::string& script, int status, const std::string& output) const {
  if (folder_.empty() || (status != 0 && status != 1)) return;
  try {
    write_file_atomically(path(script), entry(script, status, output));
  } catch (const std::exception&) {
    // A cache that cannot be written only costs time.
  }
}

// The entry's text: a header line, the sizes, Gappa's version, the script, the status, the output.
std::string ProofCache::entry(const std::string& script, int status, const std::string& output) const {
  return "billiards proof cache 1\n" + std::to_string(version_.size()) + " " + std::to_string(script.size()) +
         "\n" + version_ + script + "status " + std::to_string(status) + "\n" + output + "\n";
}

// 64-bit FNV-1a of the version and the whole script, in hex.
std::filesystem::path ProofCache::path(const std::string& script) const {
  std::uint64_t hash = 14695981039346656037ULL;
  for (const std::string* text : {&version_, &script}) {
    for (const char c : *text) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
    hash = (hash ^ 0xffU) * 1099511628211ULL;  // a separator no character equals
  }
  char name[24];
  std::snprintf(name, sizeof name, "%016llx.gappa", static_cast<unsigned long long>(hash));
  return folder_ / name;
}

GappaAnswer run_gappa(const std::string& whole) {
  const std::string script = only_what_is_read(whole);
  // The same script (a probe repeated for another guard or case) is answered once.
  static std::map<std::string, GappaAnswer> answered;
  if (const auto known = answered.find(script); known != answered.end()) return known->second;
  const auto answer = [&](int status, std::string output) {
    const bool proven = gappa_proved(status, output);
    return answered[script] = GappaAnswer{status, std::move(output), proven};
  };
  if (auto cached = ProofCache::instance().find(script))
    return answer(cached->first, std::move(cached->second));
  std::string path = (std::filesystem::temp_directory_path() / "billiards-gappa-XXXXXX").string();
  std::vector<char> name(path.begin(), path.end());
  name.push_back('\0');
  const int descriptor = mkstemp(name.data());
  if (descriptor < 0) throw std::runtime_error("cannot create a temporary file for Gappa's input");
  close(descriptor);
  path = name.data();
  {
    std::ofstream file(path);
    file << script;
  }
  const auto [status, output] = run_command("gappa '" + path + "'");
  std::filesystem::remove(path);
  if (status == not_run) throw std::runtime_error("cannot run Gappa");
  ProofCache::instance().keep(script, status, output);
  return answer(status, output);
}

}  // namespace billiards::derive
