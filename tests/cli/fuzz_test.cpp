// Structure-aware fuzzing of everything tcsb reads from a file: suites (`validate`, `run`), result files
// (`compare`, `export`), shards (`merge`), runs and shard sets (`tax`), calibration files (`validate`, `run`) and
// suites with huge lists (`validate` under an address-space limit). Each case takes a valid document, applies one to
// three seeded mutations — to its parsed structure (a value deleted, retyped, replaced by an extreme, a key renamed, an
// array shuffled) or to its text (cut short, NUL and garbage appended, a number overflowing to infinity, nesting
// thousands deep, a byte flipped) — and runs the real executable on it. Whatever the input, tcsb must end in one of two
// ways:
//   - exit 0 (or 1 where the command judges: compare), with well-formed output, or
//   - exit 2 with exactly one line on stderr, and no output file left behind (nor any stray temporary file);
// never a signal, a hang, exit 3 ("internal error") or another code. The generator is seeded, so a failure names
// the case that reproduces it; the case count is TCSB_FUZZ_CASES (fewer under the sanitizers, where each process
// start costs more).
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <csignal>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "cli_fixture.h"

#ifndef TCSB_FUZZ_CASES
#define TCSB_FUZZ_CASES 1000
#endif

namespace {

using namespace tcsb::cli_test;
using ojson = nlohmann::ordered_json;

/// Longest any single case may run before it counts as a hang (a run of the 9x9 suite takes well under a second).
constexpr unsigned kCaseTimeoutS = 30;
/// Failures listed in full before the rest are only counted.
constexpr int kFailuresShown = 8;

/// How one process ended.
struct Ended {
  int exit_code = -1;  ///< -1 when killed by a signal
  int signal = 0;      ///< the signal, 0 when it exited
  std::string err;     ///< its stderr
};

/// Runs TCSB_BINARY with `args` in `dir` (no shell, so no quoting can go wrong), stdout and stderr to files there,
/// killed by SIGALRM after kCaseTimeoutS; with `address_space` (bytes), under that RLIMIT_AS.
Ended run_tcsb(const fs::path& dir, const std::vector<std::string>& args, std::uint64_t address_space = 0) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    if (address_space > 0) {  // `ulimit -v`: a guard that expands before it counts dies here, not in CI's memory
      const struct rlimit limit { address_space, address_space };
      if (::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(126);
    }
    const int out = ::open("stdout.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
    std::vector<char*> argv{const_cast<char*>(TCSB_BINARY)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::alarm(kCaseTimeoutS);  // survives exec: a hang ends as SIGALRM
    ::execv(TCSB_BINARY, argv.data());
    ::_exit(127);
  }
  Ended e;
  int status = 0;
  if (pid < 0 || ::waitpid(pid, &status, 0) != pid) return e;
  if (WIFEXITED(status)) e.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) e.signal = WTERMSIG(status);
  e.err = read_file(dir / "stderr.txt");
  return e;
}

/// Seeded mutations of JSON documents, structural and textual.
class Mutator {
 public:
  /// `extremes`: whether numbers may become huge (false for documents that are run, not only parsed: a suite asking
  /// for a billion warm-up steps is valid and would simply run for hours).
  Mutator(std::uint64_t seed, bool extremes) : rng_(seed), extremes_(extremes) {}

  /// `doc` with 1-3 mutations, as text; `log` says which, for the failure message.
  std::string mutate(const ojson& doc, std::string& log) {
    ojson j = doc;
    const int structural = pick(0, 3);
    for (int i = 0; i < structural; ++i) mutate_structure(j, log);
    std::string text = j.dump(2);
    if (structural == 0 || chance(0.25)) mutate_text(text, log);
    return text;
  }

 private:
  int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool chance(double p) { return std::bernoulli_distribution(p)(rng_); }
  template <typename T>
  const T& one_of(const std::vector<T>& items) {
    return items[static_cast<std::size_t>(pick(0, static_cast<int>(items.size()) - 1))];
  }

  /// Every value's JSON pointer, the root included.
  static void pointers(const ojson& j, const ojson::json_pointer& at, std::vector<ojson::json_pointer>& out) {
    out.push_back(at);
    if (j.is_object()) {
      for (const auto& [key, value] : j.items()) pointers(value, at / key, out);
    } else if (j.is_array()) {
      for (std::size_t i = 0; i < j.size(); ++i) pointers(j[i], at / i, out);
    }
  }

  ojson replacement() {
    static const std::vector<ojson> kTame = {nullptr,
                                             true,
                                             false,
                                             0,
                                             -1,
                                             1,
                                             2,
                                             0.5,
                                             -0.5,
                                             1e-300,
                                             "",
                                             "x",
                                             ojson::array(),
                                             ojson::object(),
                                             ojson::array({ojson::array()}),
                                             "\x1b[31mred\x07\r\nnext",
                                             std::string(3000, 'k')};
    static const std::vector<ojson> kExtreme = {
        2147483647, 2147483648LL, -2147483649LL, 9223372036854775807LL, 18446744073709551615ULL, 1e308, -1e308,
        4.9e-324,   1e15,         123456789.5};
    return extremes_ && chance(0.4) ? one_of(kExtreme) : one_of(kTame);
  }

  void mutate_structure(ojson& j, std::string& log) {
    std::vector<ojson::json_pointer> all;
    pointers(j, ojson::json_pointer(), all);
    const ojson::json_pointer at = one_of(all);
    ojson& v = j[at];
    const std::string where = at.to_string().empty() ? "/" : at.to_string();
    switch (pick(0, 7)) {
      case 0:  // delete (the root cannot be: replace it instead)
        if (!at.empty()) {
          ojson& parent = j[at.parent_pointer()];
          if (parent.is_object()) {
            parent.erase(at.back());
          } else {
            parent.erase(static_cast<std::size_t>(std::stoul(at.back())));
          }
          log += " delete " + where + ";";
          return;
        }
        [[fallthrough]];
      case 1:
      case 2:
        v = replacement();
        log += " replace " + where + " with " + v.dump().substr(0, 40) + ";";
        return;
      case 3:  // scale a number
        if (v.is_number()) {
          const std::vector<double> factors = extremes_ ? std::vector<double>{-1, 0, 10, 1e6, 1e-6, 1.0000001}
                                                        : std::vector<double>{-1, 0, 0.5, 1.0000001};
          const double f = one_of(factors);
          v = v.get<double>() * f;
          log += " scale " + where + " by " + std::to_string(f) + ";";
          return;
        }
        [[fallthrough]];
      case 4:  // an unknown key, or an extra element
        if (v.is_object()) {
          v["zz_unknown_" + std::to_string(pick(0, 99))] = replacement();
          log += " add key to " + where + ";";
        } else if (v.is_array()) {
          v.push_back(v.empty() ? replacement() : v[0]);
          log += " append to " + where + ";";
        } else {
          v = ojson::array({v});
          log += " wrap " + where + " in an array;";
        }
        return;
      case 5:  // rename a key
        if (v.is_object() && !v.empty()) {
          const std::string key = v.begin().key();
          ojson moved = v[key];
          v.erase(key);
          v[key + "\t\x01"] = moved;
          log += " rename " + where + "/" + key + ";";
          return;
        }
        [[fallthrough]];
      case 6:  // reorder an array, or retype a container
        if (v.is_array() && v.size() > 1) {
          std::shuffle(v.begin(), v.end(), rng_);
          log += " shuffle " + where + ";";
        } else if (v.is_object()) {
          ojson as_array = ojson::array();
          for (const auto& item : v.items()) as_array.push_back(item.value());
          v = as_array;
          log += " object->array " + where + ";";
        } else {
          v = v.dump();
          log += " stringify " + where + ";";
        }
        return;
      default:  // the same value twice in a row: duplicate an array element in place
        if (v.is_array() && !v.empty()) {
          v.insert(v.begin(), v[0]);
          log += " duplicate first element of " + where + ";";
        } else {
          v = nullptr;
          log += " null " + where + ";";
        }
        return;
    }
  }

  void mutate_text(std::string& text, std::string& log) {
    switch (pick(0, 5)) {
      case 0: {
        const std::size_t cut = static_cast<std::size_t>(pick(0, static_cast<int>(text.size())));
        text.resize(cut);
        log += " cut at byte " + std::to_string(cut) + ";";
        return;
      }
      case 1:
        text += std::string("\0garbage{[\"", 11);
        log += " NUL and garbage appended;";
        return;
      case 2: {  // a number that overflows a double
        const std::size_t digit = text.find_first_of("0123456789");
        if (digit != std::string::npos) text.replace(digit, 1, chance(0.5) ? "1e309" : "-1e309");
        log += " a number overflows to infinity;";
        return;
      }
      case 3: {  // nesting far deeper than any parser's stack should allow
        const int depth = chance(0.5) ? 100000 : pick(100, 5000);
        text = std::string(static_cast<std::size_t>(depth), '[') + text +
               std::string(static_cast<std::size_t>(depth), ']');
        log += " nested " + std::to_string(depth) + " deep;";
        return;
      }
      case 4: {
        if (text.empty()) return;
        const std::size_t at = static_cast<std::size_t>(pick(0, static_cast<int>(text.size()) - 1));
        text[at] = static_cast<char>(pick(0, 255));
        log += " byte " + std::to_string(at) + " flipped;";
        return;
      }
      default:
        text = "\xef\xbb\xbf" + text;  // a byte-order mark
        log += " BOM prefixed;";
        return;
    }
  }

  std::mt19937_64 rng_;
  bool extremes_;
};

/// What the files in the case directory may be after a case: anything else is a stray file tcsb left behind.
bool only_expected_files(const fs::path& dir, const std::set<std::string>& allowed, std::string& stray) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (!allowed.count(name)) {
      stray = name;
      return false;
    }
  }
  return true;
}

/// Whether `path` holds a JSON object with "tool": "tcsb".
bool is_tcsb_document(const fs::path& path) {
  try {
    const ojson doc = ojson::parse(read_file(path));
    return doc.is_object() && doc.value("tool", "") == "tcsb";
  } catch (const std::exception&) {
    return false;
  }
}

class Fuzz : public Cli {
 protected:
  /// Checks one case's ending; `judges`: exit 1 is a legitimate verdict of this command. Returns "" when fine.
  static std::string problem(const Ended& e, bool judges) {
    if (e.signal != 0) return "killed by signal " + std::to_string(e.signal) + (e.signal == SIGALRM ? " (hang)" : "");
    if (e.exit_code == 0 || (judges && e.exit_code == 1)) return "";
    if (e.exit_code != 2) return "exit " + std::to_string(e.exit_code) + ": " + e.err.substr(0, 300);
    if (count_lines(e.err) != 1 || e.err.rfind("tcsb: error: ", 0) != 0)
      return "exit 2 without exactly one error line: " + e.err.substr(0, 300);
    return "";
  }

  void record(const std::string& what, int index, const std::string& log, const std::string& why) {
    ++failures_;
    if (failures_ <= kFailuresShown) ADD_FAILURE() << what << " case " << index << ":" << log << " -> " << why;
  }

  void TearDown() override {
    if (failures_ > kFailuresShown) ADD_FAILURE() << failures_ - kFailuresShown << " more failing cases";
    Cli::TearDown();
  }

  int failures_ = 0;
};

/// The bundled suites and the CLI tests' 9x9 suite, as parsed documents.
std::vector<ojson> suite_corpus() {
  std::vector<ojson> corpus{ojson::parse(nine_by_nine_suite("fuzz", 2))};
  for (const auto& entry : fs::directory_iterator(fs::path(TCSB_SOURCE_DIR) / "suites")) {
    if (entry.path().extension() == ".json") corpus.push_back(ojson::parse(read_file(entry.path())));
  }
  return corpus;
}

TEST_F(Fuzz, ValidateParsesMutatedSuitesOrRefusesThemInOneLine) {
  const std::vector<ojson> corpus = suite_corpus();
  Mutator mutator(20261124, /*extremes=*/true);
  const int cases = TCSB_FUZZ_CASES;
  for (int i = 0; i < cases; ++i) {
    std::string log;
    write_file(dir_ / "suite.json", mutator.mutate(corpus[static_cast<std::size_t>(i) % corpus.size()], log));
    const Ended e = run_tcsb(dir_, {"validate", "suite.json"});
    if (const std::string why = problem(e, /*judges=*/false); !why.empty()) record("validate", i, log, why);
  }
}

TEST_F(Fuzz, RunWritesAResultOrRefusesAndWritesNothing) {
  const ojson suite = ojson::parse(nine_by_nine_suite("fuzz", 2));
  Mutator mutator(424242, /*extremes=*/false);
  const int cases = TCSB_FUZZ_CASES / 5;  // each one runs a simulation
  for (int i = 0; i < cases; ++i) {
    std::string log;
    write_file(dir_ / "suite.json", mutator.mutate(suite, log));
    fs::remove(dir_ / "out.json");
    const Ended e = run_tcsb(dir_, {"run", "suite.json", "--quiet", "--out", "out.json"});
    std::string why = problem(e, /*judges=*/false);
    std::string stray;
    if (why.empty() && e.exit_code == 0 && !is_tcsb_document(dir_ / "out.json")) why = "exit 0 without a result";
    if (why.empty() && e.exit_code != 0 && fs::exists(dir_ / "out.json")) why = "refused, but wrote out.json";
    if (why.empty() && !only_expected_files(dir_, {"suite.json", "out.json", "stdout.txt", "stderr.txt"}, stray))
      why = "left a stray file: " + stray;
    if (!why.empty()) record("run", i, log, why);
  }
}

TEST_F(Fuzz, CompareAndExportReadMutatedResultsOrRefuseThemInOneLine) {
  write_file(dir_ / "suite.json", nine_by_nine_suite("fuzz", 2));
  const Ended made = run_tcsb(dir_, {"run", "suite.json", "--quiet", "--out", "base.json"});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  const ojson base = ojson::parse(read_file(dir_ / "base.json"));
  Mutator mutator(777, /*extremes=*/true);
  const std::set<std::string> allowed{"suite.json", "base.json", "new.json", "out.json", "stdout.txt", "stderr.txt"};
  const int cases = TCSB_FUZZ_CASES / 2;  // each one starts the executable twice
  for (int i = 0; i < cases; ++i) {
    std::string log;
    write_file(dir_ / "new.json", mutator.mutate(base, log));
    // Both orders: a broken baseline must be refused as surely as a broken new run.
    const std::vector<std::string> compare = i % 2 == 0 ? std::vector<std::string>{"compare", "base.json", "new.json"}
                                                        : std::vector<std::string>{"compare", "new.json", "base.json"};
    // compare prints its Markdown summary on stderr when it decides, so only its refusals must be one line.
    if (const std::string why = problem(run_tcsb(dir_, compare), /*judges=*/true); !why.empty())
      record("compare", i, log, why);

    fs::remove(dir_ / "out.json");
    const Ended e = run_tcsb(dir_, {"export", "new.json", "--format", "gbench", "--out", "out.json"});
    std::string why = problem(e, /*judges=*/false);
    std::string stray;
    if (why.empty() && e.exit_code == 0 && !fs::exists(dir_ / "out.json")) why = "exit 0 without output";
    if (why.empty() && e.exit_code != 0 && fs::exists(dir_ / "out.json")) why = "refused, but wrote out.json";
    if (why.empty() && !only_expected_files(dir_, allowed, stray)) why = "left a stray file: " + stray;
    if (!why.empty()) record("export", i, log, why);
  }
}

// ---- issue 38: the surfaces added since the first round -----------------------------------------------------------

/// The 9x9 suite with two nets and plain_equal, so it shards, merges and has a tax to judge.
std::string two_net_suite(int repetitions) {
  std::string suite = nine_by_nine_suite("fuzz", repetitions);
  const std::string methods = R"("methods": ["plain", "tcsb"])";
  suite.replace(suite.find(methods), methods.size(), R"("methods": ["plain", "tcsb", "plain_equal"])");
  const std::size_t at = suite.find(R"({"name": "n9")");
  const std::size_t end = suite.find("}]", at) + 1;
  std::string second = suite.substr(at, end - at);
  second.replace(second.find("n9"), 2, "m9");
  suite.insert(end, ", " + second);
  return suite;
}

/// Checks a command that writes `out` (in `dir`): refusals leave no out (nor anything else), successes a tcsb
/// document. `verdicts`: exit 1 and 4 are judgements of this command, with their output written.
std::string written_problem(const Ended& e, const fs::path& dir, const std::string& out,
                            const std::set<std::string>& allowed, bool verdicts) {
  if (e.signal != 0) return "killed by signal " + std::to_string(e.signal) + (e.signal == SIGALRM ? " (hang)" : "");
  const bool wrote = e.exit_code == 0 || (verdicts && (e.exit_code == 1 || e.exit_code == 4));
  if (!wrote && e.exit_code != 2) return "exit " + std::to_string(e.exit_code) + ": " + e.err.substr(0, 300);
  if (!wrote && (count_lines(e.err) != 1 || e.err.rfind("tcsb: error: ", 0) != 0))
    return "exit 2 without exactly one error line: " + e.err.substr(0, 300);
  if (wrote && !is_tcsb_document(dir / out)) return "exit " + std::to_string(e.exit_code) + " without " + out;
  if (!wrote && fs::exists(dir / out)) return "refused, but wrote " + out;
  std::string stray;
  if (!only_expected_files(dir, allowed, stray)) return "left a stray file: " + stray;
  return "";
}

TEST_F(Fuzz, MergeJoinsMutatedShardsOrRefusesThemAndWritesNothing) {
  write_file(dir_ / "suite.json", two_net_suite(2));
  for (const char* k : {"1", "2"}) {
    const Ended made = run_tcsb(dir_, {"run", "suite.json", "--quiet", "--shard", std::string(k) + "/2", "--out",
                                       std::string("s") + k + ".json"});
    ASSERT_EQ(made.exit_code, 0) << made.err;
  }
  const std::vector<ojson> shards{ojson::parse(read_file(dir_ / "s1.json")), ojson::parse(read_file(dir_ / "s2.json"))};
  Mutator mutator(38001, /*extremes=*/true);
  const std::set<std::string> allowed{"suite.json", "s1.json",    "s2.json",   "bad.json",
                                      "out.json",   "stdout.txt", "stderr.txt"};
  const int cases = TCSB_FUZZ_CASES / 12;
  for (int i = 0; i < cases; ++i) {
    std::string log;
    const std::size_t mutated = static_cast<std::size_t>(i % 2);
    write_file(dir_ / "bad.json", mutator.mutate(shards[mutated], log));
    fs::remove(dir_ / "out.json");
    const Ended e = run_tcsb(dir_, {"merge", mutated == 0 ? "bad.json" : "s1.json",
                                    mutated == 1 ? "bad.json" : "s2.json", "--quiet", "--out", "out.json"});
    if (const std::string why = written_problem(e, dir_, "out.json", allowed, false); !why.empty())
      record("merge", i, log, why);
  }
}

TEST_F(Fuzz, TaxJudgesMutatedRunsAndShardSetsOrRefusesThem) {
  write_file(dir_ / "suite.json", two_net_suite(5));
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"run", "suite.json", "--quiet", "--out", "a.json"},
        std::vector<std::string>{"run", "suite.json", "--quiet", "--out", "b.json"},
        std::vector<std::string>{"run", "suite.json", "--quiet", "--shard", "1/2", "--out", "s1.json"},
        std::vector<std::string>{"run", "suite.json", "--quiet", "--shard", "2/2", "--out", "s2.json"}}) {
    const Ended made = run_tcsb(dir_, args);
    ASSERT_EQ(made.exit_code, 0) << made.err;
  }
  const std::vector<std::string> files{"a.json", "b.json", "s1.json", "s2.json"};
  std::vector<ojson> docs;
  for (const std::string& f : files) docs.push_back(ojson::parse(read_file(dir_ / f)));
  Mutator mutator(38002, /*extremes=*/true);
  const std::set<std::string> allowed{"suite.json", "a.json",   "b.json",     "s1.json",   "s2.json",
                                      "bad.json",   "out.json", "stdout.txt", "stderr.txt"};
  const int cases = TCSB_FUZZ_CASES / 12;
  for (int i = 0; i < cases; ++i) {
    std::string log;
    // Two runs, or a shard set; one of the pair mutated.
    const std::size_t first = i % 2 == 0 ? 0 : 2, mutated = first + static_cast<std::size_t>((i / 2) % 2);
    write_file(dir_ / "bad.json", mutator.mutate(docs[mutated], log));
    fs::remove(dir_ / "out.json");
    std::vector<std::string> args{"tax"};
    for (std::size_t k = first; k < first + 2; ++k) args.push_back(k == mutated ? "bad.json" : files[k]);
    for (const char* flag : {"--min-nodes", "1", "--compression", "0.5", "--out", "out.json"}) args.push_back(flag);
    if (i % 3 == 0) args.push_back("--over-nets");
    if (const std::string why = written_problem(run_tcsb(dir_, args), dir_, "out.json", allowed, true); !why.empty())
      record("tax", i, log, why);
  }
}

TEST_F(Fuzz, MutatedCalibrationFilesAreUsedOrRefusedByValidateAndRun) {
  write_file(dir_ / "plain.json", nine_by_nine_suite("fuzz", 1));
  const Ended made = run_tcsb(dir_, {"calibrate", "plain.json", "--quiet", "--out", "good.calibration.json"});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  std::string suite = nine_by_nine_suite("fuzz", 1);
  suite.replace(suite.rfind('}'), 1, R"(, "fidelity": {"enabled": true, "calibration": "c.json"}})");
  write_file(dir_ / "suite.json", suite);
  const ojson calibration = ojson::parse(read_file(dir_ / "good.calibration.json"));
  Mutator mutator(38003, /*extremes=*/true);
  const std::set<std::string> allowed{
      "plain.json", "good.calibration.json", "suite.json", "c.json", "out.json", "stdout.txt", "stderr.txt"};
  const int cases = TCSB_FUZZ_CASES / 12;
  for (int i = 0; i < cases; ++i) {
    std::string log;
    write_file(dir_ / "c.json", mutator.mutate(calibration, log));
    if (const std::string why = problem(run_tcsb(dir_, {"validate", "suite.json"}), false); !why.empty())
      record("validate", i, log, why);
    if (i % 4 != 0) continue;  // a run simulates: every fourth
    fs::remove(dir_ / "out.json");
    const Ended e = run_tcsb(dir_, {"run", "suite.json", "--quiet", "--out", "out.json"});
    if (const std::string why = written_problem(e, dir_, "out.json", allowed, false); !why.empty())
      record("run", i, log, why);
  }
}

TEST_F(Fuzz, SuitesWithHugeListsAreCountedBeforeTheyAreExpanded) {
  // Nets (up to 2 x 10^4), compression targets and axes (up to 10^5 entries each): validated or refused in one line
  // under a 1 GiB address space (no sanitized process starts under one: there, without), never killed.
  const std::uint64_t limit = kAddressSanitized ? 0 : (1ull << 30);
  std::mt19937_64 rng(38004);
  const auto size = [&] { return std::vector<int>{1, 3, 100, 1000, 20000, 100000}[rng() % 6]; };
  const int cases = std::max(6, TCSB_FUZZ_CASES / 100);
  for (int i = 0; i < cases; ++i) {
    ojson suite = ojson::parse(nine_by_nine_suite("huge", 1));
    // Nets at most 20 000 (2 MB of suite): parsing more is slow, and their count is refused like the others'.
    const int nets = std::min(size(), 20000), targets = size(), seeds = size(), iterations = rng() % 2 ? size() : 0;
    const std::string log = " " + std::to_string(nets) + " nets, " + std::to_string(targets) + " targets, " +
                            std::to_string(seeds) + " seeds, " + std::to_string(iterations) + " iterations";
    ojson net = suite["nets"][0];
    suite["nets"] = ojson::array();
    for (int n = 0; n < nets; ++n) {
      net["name"] = "n" + std::to_string(n);
      suite["nets"].push_back(net);
    }
    suite["compression"] = ojson::array();
    for (int t = 0; t < targets; ++t) suite["compression"].push_back(1.0 - static_cast<double>(t) / (targets + 1));
    suite["axes"] = ojson::object();
    for (int k = 0; k < seeds; ++k) suite["axes"]["seed"].push_back(k);
    for (int k = 0; k < iterations; ++k) suite["axes"]["solver.piterations"].push_back(k + 1);
    write_file(dir_ / "suite.json", suite.dump());
    if (const std::string why = problem(run_tcsb(dir_, {"validate", "suite.json"}, limit), false); !why.empty())
      record("validate", i, log, why);
  }
}

// ---- issue 60: scenes, camera paths and instruction counts ----------------------------------------------------------

/// The 9x9 suite in a scene, as the viewer suites run: a sphere under the net, a camera on a keyframed path, the view
/// terms on the parallel feedback. Its camera keyframes are 0 and 12 steps apart, so a pose halfway (or a third, a
/// quarter of the way) between them is a step boundary the run meets.
ojson scene_suite() {
  ojson suite = ojson::parse(nine_by_nine_suite("fuzz", 2));
  suite["feedback"] = {{"view", true}, {"parallel", true}, {"threads", 2}};
  suite["scene"] = ojson::parse(R"({
    "colliders": [{"shape": "sphere", "position": [0, 0.5, 0], "radius": 0.5}],
    "margin": 0.02, "sdf_voxel": 0.1,
    "camera": {"fov_deg": 60, "image": [320, 240], "path": [
      {"time": 0, "position": [0, 4, 6], "target": [0, 2, 0]},
      {"time": 0.2, "position": [3, 4, 6], "target": [0, 2, 0]}]}})");
  return suite;
}

TEST_F(Fuzz, ValidateParsesMutatedScenesOrRefusesThemInOneLine) {
  // Only the scene block mutates (colliders, paths, camera, wind, pins), with extreme numbers: far more of each case
  // reaches the scene reader than whole-suite mutations do.
  const ojson suite = scene_suite();
  Mutator mutator(60001, /*extremes=*/true);
  const int cases = TCSB_FUZZ_CASES / 4;
  for (int i = 0; i < cases; ++i) {
    std::string log;
    ojson doc = suite;
    doc["scene"] = "@SCENE@";
    std::string text = doc.dump(2);
    text.replace(text.find("\"@SCENE@\""), 9, mutator.mutate(suite["scene"], log));
    write_file(dir_ / "suite.json", text);
    const Ended e = run_tcsb(dir_, {"validate", "suite.json"});
    if (const std::string why = problem(e, /*judges=*/false); !why.empty()) record("validate scene", i, log, why);
  }
}

TEST_F(Fuzz, ACameraPathThatValidatesRunsToTheEnd) {
  // Random keyframed paths of small whole coordinates: many pass over their target (looking along up) or through it
  // at a step boundary. Every pose a path reaches must give an image or the path is refused up front: a path that
  // validate passes must run to the end with the view terms on, never exit 3, hang or abort.
  ojson suite = scene_suite();
  std::mt19937 rng(60002);
  std::uniform_int_distribution<int> small(-2, 2), height(0, 5);
  const auto valid = [](const std::array<int, 3>& p, const std::array<int, 3>& t) {
    const int dx = t[0] - p[0], dz = t[2] - p[2];
    return dx != 0 || dz != 0;  // up is +y: a direction with no horizontal part looks along it (or nowhere)
  };
  // Each valid one runs a simulation; 40 at least, so the sanitized build's fewer cases still meet refused paths.
  const int cases = std::max(40, TCSB_FUZZ_CASES / 20);
  int refused = 0, ran = 0;
  for (int i = 0; i < cases; ++i) {
    ojson path = ojson::array();
    std::string log = " path";
    for (int k = 0; k < 2 + i % 2; ++k) {
      std::array<int, 3> p{}, t{};
      do {
        p = {small(rng), height(rng), small(rng)};
        t = {small(rng), 2, small(rng)};
      } while (!valid(p, t));
      if (i % 2 == 0 && k == 1) {
        // A crane shot: the horizontal direction turns to its opposite, k' times as long, so the camera looks
        // straight down (or at its target from above: along up) 1 / (1 + k') of the way, at step 6, 4 or 3 of 12.
        const auto p0 = path[0]["position"].get<std::array<int, 3>>();
        const auto t0 = path[0]["target"].get<std::array<int, 3>>();
        const int scale = 1 + static_cast<int>(rng() % 3);
        t = {t0[0], 2, t0[2]};
        p = {t[0] + scale * (t0[0] - p0[0]), height(rng), t[2] + scale * (t0[2] - p0[2])};
      }
      path.push_back({{"time", 0.2 * k}, {"position", p}, {"target", t}});
      log += " " + path.back().dump();
    }
    suite["scene"]["camera"]["path"] = path;
    write_file(dir_ / "suite.json", suite.dump(2));
    const Ended checked = run_tcsb(dir_, {"validate", "suite.json"});
    if (const std::string why = problem(checked, /*judges=*/false); !why.empty()) {
      record("validate path", i, log, why);
      continue;
    }
    if (checked.exit_code != 0) {
      ++refused;
      continue;
    }
    ++ran;
    fs::remove(dir_ / "out.json");
    const Ended e = run_tcsb(dir_, {"run", "suite.json", "--quiet", "--out", "out.json"});
    std::string why = e.signal != 0 || e.exit_code != 0
                          ? (e.signal != 0 ? "killed by signal " + std::to_string(e.signal)
                                           : "exit " + std::to_string(e.exit_code) + ": " + e.err.substr(0, 300))
                          : "";
    if (why.empty() && !is_tcsb_document(dir_ / "out.json")) why = "exit 0 without a result";
    if (!why.empty()) record("run path", i, log, why);
  }
  EXPECT_GT(refused, 0) << "no random path met a pose without an image: the generator tests nothing";
  EXPECT_GT(ran, 0);
}

TEST_F(Fuzz, CompareJudgesMutatedInstructionCountsOrRefusesThemInOneLine) {
  // A result of --measure instructions, made from a timed run (valgrind is far too slow for a fuzz corpus) with
  // counts of the size a run has; then mutated: a count removed, zeroed, retyped or made impossible must be a
  // verdict or a one-line refusal, never a pass by omission (issue 60: the gate skipped cases without counts).
  write_file(dir_ / "suite.json", nine_by_nine_suite("fuzz", 2));
  const Ended made = run_tcsb(dir_, {"run", "suite.json", "--quiet", "--out", "base.json"});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  ojson base = ojson::parse(read_file(dir_ / "base.json"));
  base["measure"] = "instructions";
  for (ojson& c : base["cases"]) {
    const std::int64_t own = c["method"] == "tcsb" ? 200000 : 0, bullet = 5000000;
    c["instructions"] = {{"own", own},
                         {"bullet", bullet},
                         {"total", own + bullet},
                         {"functions",
                          ojson::array({{{"name", "btSoftBody::PSolve_Links"}, {"instructions", bullet}},
                                        {{"name", "TcSoftBody::advance_blends"}, {"instructions", own}}})}};
  }
  write_file(dir_ / "base.json", base.dump(2));
  const Ended same = run_tcsb(dir_, {"compare", "base.json", "base.json"});
  ASSERT_EQ(same.exit_code, 0) << same.err;
  Mutator mutator(60003, /*extremes=*/true);
  const int cases = TCSB_FUZZ_CASES / 4;
  int refused = 0;
  for (int i = 0; i < cases; ++i) {
    std::string log;
    ojson counted = base;
    // Mutate within the counts most of the time: that is where the gate must fail closed.
    const std::size_t c = static_cast<std::size_t>(i) % counted["cases"].size();
    if (i % 4 != 3) {
      counted["cases"][c]["instructions"] = "@COUNTS@";
      std::string text = counted.dump(2);
      text.replace(text.find("\"@COUNTS@\""), 10, mutator.mutate(base["cases"][c]["instructions"], log));
      write_file(dir_ / "new.json", text);
    } else {
      counted["cases"][c].erase("instructions");
      log = " cases[" + std::to_string(c) + "].instructions removed";
      write_file(dir_ / "new.json", counted.dump(2));
    }
    const Ended e = run_tcsb(dir_, i % 2 == 0 ? std::vector<std::string>{"compare", "base.json", "new.json"}
                                              : std::vector<std::string>{"compare", "new.json", "base.json"});
    refused += e.exit_code == 2;
    if (const std::string why = problem(e, /*judges=*/true); !why.empty()) record("compare counts", i, log, why);
    if (i % 4 == 3 && e.exit_code != 2) record("compare counts", i, log, "a case without counts was not refused");
  }
  EXPECT_GT(refused, cases / 4);
}

}  // namespace
