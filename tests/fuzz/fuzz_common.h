/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// Shared by the libFuzzer targets: a private scratch folder, files written from fuzz bytes, and
// the one rule every target checks: bad bytes may throw InputError, nothing else.

#include <mrpt_topoeval/errors.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace mrpt_topoeval::fuzz
{
/** A scratch folder of this process, made once: libFuzzer runs one input after another in one
 * process, so files are simply overwritten (and -fork/-jobs workers get their own folder). It
 * is removed at a normal exit; a crash keeps it, with the input that crashed. */
inline const std::string& scratchDir()
{
    static const std::string dir = []
    {
        const char* base = std::getenv("TMPDIR");
        std::string tmpl = std::string(base && *base ? base : "/tmp") + "/topoeval_fuzz_XXXXXX";
        if (!mkdtemp(tmpl.data())) std::abort();
        return tmpl;
    }();
    static const bool cleanup = []
    {
        // Function-local statics are destroyed after atexit handlers registered later run, so
        // `dir` is still alive here.
        return std::atexit(
                   []
                   {
                       std::error_code ec;
                       std::filesystem::remove_all(dir, ec);
                   }) == 0;
    }();
    (void)cleanup;
    return dir;
}

inline std::string writeFile(const std::string& name, const std::uint8_t* data, std::size_t size)
{
    const std::string path = scratchDir() + "/" + name;
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!f) std::abort();  // the scratch folder itself failing is not a finding of the target
    return path;
}

/** Runs `f`; InputError is the documented answer to bad bytes. Any other exception escapes
 * and libFuzzer reports it as a crash (an uncaught exception aborts): a loader that leaks
 * MRPT's or OpenCV's raw exceptions breaks the "one-line message, exit 2" contract. */
template <class F>
void expectOnlyInputErrors(F&& f)
{
    try
    {
        f();
    }
    catch (const InputError&)
    {
    }
}

}  // namespace mrpt_topoeval::fuzz
