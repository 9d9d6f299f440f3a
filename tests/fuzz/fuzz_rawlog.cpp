/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The rawlog reader (internal, src/rawlog/RawlogReader.h): every entry until the end, a
// truncation or a corrupt entry. Each status is a documented outcome; crashes, leaks and
// exceptions other than InputError (from opening) are findings.

#include "fuzz_common.h"
#include "rawlog/RawlogReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace mrpt_topoeval;
    const bool gz = size >= 2 && data[0] == 0x1f && data[1] == 0x8b;
    const std::string path = fuzz::writeFile(gz ? "log.rawlog.gz" : "log.rawlog", data, size);
    fuzz::expectOnlyInputErrors(
        [&]
        {
            // 1 MiB per entry: the real limit is 64 MiB, smaller keeps the fuzzer fast and
            // exercises the limit check itself.
            // Classes the layout check does not know are refused: the target exercises the
            // check; MRPT's readers of other sensors trust their length fields (a residual
            // risk, doc/reliability.md).
            rawlog::RawlogReader reader(path, 1u << 20, false);
            mrpt::serialization::CSerializable::Ptr obj;
            std::string why;
            while (reader.next(obj, why) == rawlog::RawlogReader::Status::Object)
            {
            }
        });
    return 0;
}
