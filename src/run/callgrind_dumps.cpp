#include "run/callgrind_dumps.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <istream>
#include <string_view>
#include <unordered_map>

#include "case/instruction_meter.h"

namespace tcsb {
namespace {

/// The first whitespace-separated unsigned number of `text` from `pos` on; nullopt when there is none.
std::optional<std::uint64_t> number_at(std::string_view text, std::size_t& pos) {
  while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t')) ++pos;
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data() + pos, text.data() + text.size(), value);
  if (error != std::errc()) return std::nullopt;
  pos = static_cast<std::size_t>(end - text.data());
  return value;
}

/// Names as callgrind writes them: "NAME", or with compressed strings "(ID) NAME" the first time and "(ID)" after.
class NameTable {
 public:
  explicit NameTable(std::vector<std::string>& names) : names_(names) {}
  std::uint32_t intern(std::string_view spec) {
    std::string_view id;
    if (spec.starts_with('(')) {
      const std::size_t close = spec.find(')');
      if (close != std::string_view::npos) {
        id = spec.substr(0, close + 1);
        spec = spec.substr(close + 1);
        if (spec.starts_with(' ')) spec.remove_prefix(1);
        if (spec.empty()) {
          const auto known = by_id_.find(std::string(id));
          if (known != by_id_.end()) return known->second;
        }
      }
    }
    const std::string name(spec);
    auto [it, added] = by_name_.try_emplace(name, static_cast<std::uint32_t>(names_.size()));
    if (added) names_.push_back(name);
    if (!id.empty()) by_id_[std::string(id)] = it->second;
    return it->second;
  }

 private:
  std::vector<std::string>& names_;
  std::unordered_map<std::string, std::uint32_t> by_name_;
  std::unordered_map<std::string, std::uint32_t> by_id_;
};

}  // namespace

MeterDumps parse_meter_dumps(std::istream& in, const std::string& file) {
  MeterDumps out;
  NameTable names(out.names);
  const std::string trigger = std::string("desc: Trigger: Client Request: ") + kMeterDumpPrefix;
  CallgrindDump* current = nullptr;  // the meter dump being read, if the current part is one
  std::unordered_map<std::uint32_t, std::uint64_t> self;
  std::uint32_t function = 0;
  bool in_function = false, after_calls = false;
  std::size_t positions = 1;  // position columns before the costs ("positions: line" by default)
  std::size_t line_number = 0;
  const auto fail = [&](const std::string& problem) {
    throw CallgrindFileError(file + ": line " + std::to_string(line_number) + ": " + problem);
  };
  const auto close_part = [&] {
    if (current) {
      for (const auto& [name, cost] : self)
        if (cost > 0) current->functions.emplace_back(name, cost);
      // By function name index, so the order does not depend on the hash map's.
      std::sort(current->functions.begin(), current->functions.end());
    }
    current = nullptr;
    self.clear();
    in_function = after_calls = false;
  };
  std::string line;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string_view l(line);
    if (l.starts_with("part:")) {
      close_part();
    } else if (l.starts_with(trigger)) {
      close_part();  // before the vector may grow: `current` points into it
      std::size_t pos = trigger.size();
      const std::optional<std::uint64_t> n = number_at(l, pos);
      if (!n) fail("a meter dump without a number");
      if (*n >= out.dumps.size()) out.dumps.resize(*n + 1);
      if (out.dumps[*n]) fail("dump " + std::to_string(*n) + " twice");
      current = &out.dumps[*n].emplace();
    } else if (l.starts_with("positions:")) {
      positions = 0;
      for (std::size_t pos = 10; pos < l.size();) {
        while (pos < l.size() && l[pos] == ' ') ++pos;
        if (pos < l.size()) ++positions;
        while (pos < l.size() && l[pos] != ' ') ++pos;
      }
    } else if (!current) {
      continue;  // another dump's lines
    } else if (l.starts_with("summary:")) {
      std::size_t pos = 8;
      const std::optional<std::uint64_t> n = number_at(l, pos);
      if (!n) fail("summary without a count");
      current->instructions = *n;
    } else if (l.starts_with("fn=")) {
      function = names.intern(l.substr(3));
      in_function = true;
      after_calls = false;
    } else if (l.starts_with("cfn=")) {
      names.intern(l.substr(4));  // registers a compressed name first written in a call
    } else if (l.starts_with("calls=")) {
      after_calls = true;  // the next cost line is the call's inclusive cost, not the caller's own
    } else if (!l.empty() &&
               (std::isdigit(static_cast<unsigned char>(l[0])) || l[0] == '+' || l[0] == '-' || l[0] == '*')) {
      if (after_calls) {
        after_calls = false;
        continue;
      }
      if (!in_function) fail("a cost line outside a function");
      std::size_t pos = 0;
      for (std::size_t column = 0; column < positions && pos != std::string_view::npos; ++column) {
        pos = l.find_first_not_of(" \t", pos);  // past the positions (numbers, +N, -N or *)
        if (pos != std::string_view::npos) pos = l.find_first_of(" \t", pos);
      }
      const std::optional<std::uint64_t> cost = pos == std::string_view::npos ? std::nullopt : number_at(l, pos);
      if (!cost) fail("a cost line without a cost");
      self[function] += *cost;
    }
  }
  if (in.bad()) throw CallgrindFileError(file + ": cannot be read");
  close_part();
  return out;
}

MeterDumps read_meter_dumps(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw CallgrindFileError(file.string() + ": cannot be opened");
  return parse_meter_dumps(in, file.string());
}

}  // namespace tcsb
