// The readers behind the memory guard, on text as the kernel writes it: no real cgroup or limit needed.
#include "base/memory_limits.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

namespace tcsb {
namespace {

TEST(MemoryLimits, MemAvailable) {
  const char* meminfo = "MemTotal:       16303412 kB\nMemFree:         1234567 kB\nMemAvailable:    8000000 kB\n";
  EXPECT_EQ(parse_mem_available(meminfo), 8000000ull * 1024);
  EXPECT_FALSE(parse_mem_available("MemTotal: 1 kB\n"));
  EXPECT_FALSE(parse_mem_available(""));
  EXPECT_FALSE(parse_mem_available("MemAvailable: lots kB\n"));
}

TEST(MemoryLimits, StatusFields) {
  const char* status = "Name:\ttcsb\nVmPeak:\t  20000 kB\nVmSize:\t   12345 kB\nVmData:\t    678 kB\n";
  EXPECT_EQ(parse_status_bytes(status, "VmSize"), 12345ull * 1024);
  EXPECT_EQ(parse_status_bytes(status, "VmData"), 678ull * 1024);
  EXPECT_FALSE(parse_status_bytes(status, "VmSwap"));
  EXPECT_FALSE(parse_status_bytes(status, "Vm"));  // a prefix of a key is not the key
}

TEST(MemoryLimits, CgroupV2Path) {
  EXPECT_EQ(cgroup_v2_path("0::/user.slice/user-1000.slice/session-2.scope\n"),
            "/user.slice/user-1000.slice/session-2.scope");
  EXPECT_EQ(cgroup_v2_path("0::/\n"), "/");
  // Hybrid: v1 controllers and the v2 line side by side.
  EXPECT_EQ(cgroup_v2_path("4:memory:/docker/abc\n1:name=systemd:/docker/abc\n0::/docker/abc\n"), "/docker/abc");
  EXPECT_FALSE(cgroup_v2_path("4:memory:/docker/abc\n"));
}

TEST(MemoryLimits, CgroupV1MemoryPath) {
  EXPECT_EQ(cgroup_v1_memory_path("9:name=systemd:/\n4:memory:/process_api/6286\n0::/\n"), "/process_api/6286");
  EXPECT_EQ(cgroup_v1_memory_path("3:cpu,memory,blkio:/job/7\n"), "/job/7");
  EXPECT_FALSE(cgroup_v1_memory_path("3:cpu,cpuacct:/job/7\n0::/\n"));
  EXPECT_FALSE(cgroup_v1_memory_path("4:memory_pressure:/x\n"));  // a controller that only starts with "memory"
}

TEST(MemoryLimits, CgroupLimit) {
  EXPECT_EQ(parse_cgroup_limit("1073741824\n"), 1073741824ull);
  EXPECT_FALSE(parse_cgroup_limit("max\n"));                  // v2: no limit
  EXPECT_FALSE(parse_cgroup_limit("9223372036854771712\n"));  // v1: no limit
  EXPECT_FALSE(parse_cgroup_limit(""));                       // file missing
}

// A fake cgroup tree: the container's level (a) has the tight limit, our own level (a/b) a loose one, the root none.
TEST(MemoryLimits, CgroupHeadroomIsTheTightestLevel) {
  const std::filesystem::path root =
      std::filesystem::temp_directory_path() / ("tcsb_cgroup_" + std::to_string(::getpid()));
  std::filesystem::remove_all(root);
  std::filesystem::create_directories(root / "a" / "b");
  const auto put = [](const std::filesystem::path& p, const char* text) { std::ofstream(p) << text; };
  put(root / "memory.max", "max\n");
  put(root / "memory.current", "999999\n");
  put(root / "a" / "memory.max", "1000\n");
  put(root / "a" / "memory.current", "400\n");
  put(root / "a" / "b" / "memory.max", "5000\n");
  put(root / "a" / "b" / "memory.current", "100\n");
  EXPECT_EQ(cgroup_headroom(root, "/a/b", "memory.max", "memory.current"), 600u);
  EXPECT_EQ(cgroup_headroom(root, "/a/b/", "memory.max", "memory.current"), 600u);
  EXPECT_EQ(cgroup_headroom(root, "/", "memory.max", "memory.current"), std::nullopt);  // "max": no limit
  // A path not visible under the mount (another namespace's): only the levels that exist count.
  EXPECT_EQ(cgroup_headroom(root, "/a/elsewhere", "memory.max", "memory.current"), 600u);
  EXPECT_EQ(cgroup_headroom(root, "/../a", "memory.max", "memory.current"), std::nullopt);  // never climbs out
  std::filesystem::remove_all(root);
}

TEST(MemoryLimits, SmallestHeadroomWins) {
  EXPECT_EQ(headroom(100, 30), 70u);
  EXPECT_EQ(headroom(100, 130), 0u);  // over the limit already: nothing left, not a wrapped-around huge number
  EXPECT_FALSE(smallest_headroom({}));
  const std::optional<MemoryHeadroom> h =
      smallest_headroom({{"MemAvailable", 8000}, {"cgroup memory.max", 500}, {"ulimit -v (RLIMIT_AS)", 900}});
  ASSERT_TRUE(h);
  EXPECT_EQ(h->source, "cgroup memory.max");
  EXPECT_EQ(h->bytes, 500u);
}

TEST(MemoryLimits, ThisProcessHasMemAvailable) {
  bool found = false;
  for (const MemoryHeadroom& h : memory_headrooms()) found |= h.source == "MemAvailable" && h.bytes > 0;
  EXPECT_TRUE(found) << "Linux always has /proc/meminfo";
}

}  // namespace
}  // namespace tcsb
