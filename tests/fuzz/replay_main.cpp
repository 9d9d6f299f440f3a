/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Replays files through a fuzz target's LLVMFuzzerTestOneInput without libFuzzer, so that the
// inputs fuzzing once found (tests/data/fuzz_regressions/TARGET/) stay fixed in every normal
// build (ctest: fuzz_replay_TARGET; doc/reliability.md).
//
//   replay_TARGET [--max-alloc-mb N] [--address-space-mb N] FILE_OR_FOLDER...
//
// An input fails when the target throws anything (InputError is caught by the target itself),
// crashes, or allocates more than it may: bad input must be refused before a large
// allocation, and the loaders catch std::bad_alloc (a refused allocation would otherwise pass
// as a clean "out of memory" message). So, outside sanitizer builds:
// - RLIMIT_AS caps the address space (default 1536 MB): an allocation MRPT makes through
//   malloc or its aligned allocator fails instead of thrashing the machine;
// - operator new is replaced to note the largest single request of each input, which fails
//   the input above --max-alloc-mb (default 256; the targets cap maps at 10^6 cells and rawlog
//   entries at 1 MiB, so legitimate requests stay far below).
// Sanitizer builds (TOPOEVAL_SANITIZE) reserve terabytes of shadow memory and bring their own
// operator new: both checks are off there, the inputs still run.

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <string>
#include <vector>

#if defined(__SANITIZE_ADDRESS__) || defined(TOPOEVAL_REPLAY_SANITIZED)
#define TOPOEVAL_REPLAY_CHECKS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define TOPOEVAL_REPLAY_CHECKS 0
#endif
#endif
#ifndef TOPOEVAL_REPLAY_CHECKS
#define TOPOEVAL_REPLAY_CHECKS 1
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace
{
std::atomic<std::size_t> g_largest_request{0};
}  // namespace

#if TOPOEVAL_REPLAY_CHECKS
// The other forms (new[], nothrow) forward to this one in libstdc++; the default operator
// delete calls free(), which matches.
void* operator new(std::size_t n)
{
    std::size_t seen = g_largest_request.load(std::memory_order_relaxed);
    while (n > seen && !g_largest_request.compare_exchange_weak(seen, n))
    {
    }
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
#endif

namespace
{
namespace fs = std::filesystem;

int usage()
{
    std::fprintf(stderr,
                 "usage: replay [--max-alloc-mb N] [--address-space-mb N] FILE_OR_FOLDER...\n");
    return 2;
}

std::string mb(std::size_t bytes) { return std::to_string(bytes >> 20) + " MB"; }

}  // namespace

int main(int argc, char** argv)
{
    std::size_t max_alloc_mb = 256;
    std::size_t address_space_mb = 1536;
    std::vector<fs::path> files;
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        if ((a == "--max-alloc-mb" || a == "--address-space-mb") && i + 1 < argc)
        {
            const unsigned long v = std::strtoul(argv[++i], nullptr, 10);
            if (v == 0) return usage();
            (a == "--max-alloc-mb" ? max_alloc_mb : address_space_mb) = v;
            continue;
        }
        if (!a.empty() && a[0] == '-') return usage();
        std::error_code ec;
        if (fs::is_directory(a, ec))
        {
            for (const auto& e : fs::directory_iterator(a))
                if (e.is_regular_file()) files.push_back(e.path());
        }
        else if (fs::is_regular_file(a, ec))
        {
            files.emplace_back(a);
        }
        else
        {
            std::fprintf(stderr, "replay: %s: no such file or folder\n", a.c_str());
            return 2;
        }
    }
    if (files.empty())
    {
        // A regression folder without inputs is a mistake (wrong path), not a pass.
        std::fprintf(stderr, "replay: no input files given\n");
        return usage();
    }
    std::sort(files.begin(), files.end());

#if TOPOEVAL_REPLAY_CHECKS
    const rlimit as{address_space_mb << 20, address_space_mb << 20};
    if (setrlimit(RLIMIT_AS, &as) != 0) std::perror("replay: setrlimit(RLIMIT_AS)");
    std::printf("replay: %zu inputs, address space %zu MB, largest allocation %zu MB\n",
                files.size(), address_space_mb, max_alloc_mb);
#else
    std::printf("replay: %zu inputs (sanitizer build: no memory limits)\n", files.size());
#endif
    int failed = 0;
    for (const fs::path& f : files)
    {
        std::ifstream in(f, std::ios::binary);
        const std::vector<std::uint8_t> data((std::istreambuf_iterator<char>(in)),
                                             std::istreambuf_iterator<char>());
        if (!in.eof() && in.fail())
        {
            std::printf("FAIL %s: cannot be read\n", f.c_str());
            ++failed;
            continue;
        }
        // Named before it runs: a crash ends the replay, and the last name is the culprit.
        std::printf("%s (%zu bytes): ", f.filename().c_str(), data.size());
        std::fflush(stdout);
        g_largest_request.store(0);
        const auto t0 = std::chrono::steady_clock::now();
        std::string problem;
        try
        {
            LLVMFuzzerTestOneInput(data.data(), data.size());
        }
        catch (const std::bad_alloc&)
        {
            problem = "std::bad_alloc escaped (an allocation over the address-space limit)";
        }
        catch (const std::exception& e)
        {
            problem = std::string("exception escaped: ") + e.what();
        }
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        const std::size_t largest = g_largest_request.load();
        if (problem.empty() && TOPOEVAL_REPLAY_CHECKS && largest > (max_alloc_mb << 20))
            problem =
                "asked for " + mb(largest) + " at once (limit " + mb(max_alloc_mb << 20) + ")";
        std::printf("%s, %.0f ms%s%s\n", problem.empty() ? "ok" : "FAIL", ms,
                    problem.empty() ? "" : ": ", problem.c_str());
        std::fflush(stdout);
        failed += !problem.empty();
    }
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    std::printf("replay: %zu inputs, %d failed, peak RSS %ld MB\n", files.size(), failed,
                ru.ru_maxrss / 1024);
    return failed ? 1 : 0;
}
