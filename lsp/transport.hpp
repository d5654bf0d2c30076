// The base protocol of LSP 3.17: messages framed by a `Content-Length` header on a byte stream
// (stdin/stdout, or a pipe in the tests). Only framing lives here; what a body means is
// jsonrpc.hpp's business.
//
// A client that breaks the framing does not stop the server: bytes that are not a header are
// skipped up to the next `Content-Length:` (and said so), a header without a usable length is
// reported and skipped, and a body the caller finds broken can be handed back in part
// (`unread`) when it swallowed the next message's header (a Content-Length too large).
#pragma once

#include <cstddef>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

namespace kerf::lsp {

struct Frame {
    std::string body;
    std::string problem;   // a framing problem (skipped bytes, a bad header); body is empty then
};

class Transport {
public:
    static constexpr std::size_t kMaxBody = std::size_t{1} << 30;   // 1 GiB: more is not a message

    Transport(int in_fd, int out_fd);
    ~Transport();
    Transport(const Transport&) = delete;
    Transport& operator=(const Transport&) = delete;

    // The next frame; nullopt at the end of the input. Blocks. One reader thread only.
    std::optional<Frame> read();
    // Puts bytes back in front of the input (a body that held the start of the next message).
    void unread(std::string_view bytes);

    // Makes a blocked read() return the end of the input (the server is stopping).
    void interrupt();

    // Writes one message. Thread-safe; false once the output is gone (the client closed it).
    bool write(std::string_view body);

private:
    bool fill();   // reads more bytes into the buffer; false at the end of the input
    // Reads at most `max` bytes into `into` once the input (or the interruption) is there; 0 at the end.
    std::size_t read_some(char* into, std::size_t max);
    std::optional<std::string> header_line(Frame& frame);
    void resync(Frame& frame);

    int in_, out_;
    int wake_[2] = {-1, -1};   // a pipe: interrupt() writes, read() polls it beside the input
    std::string buffer_;
    std::size_t pos_ = 0;
    bool eof_ = false;
    bool resync_pending_ = false;   // skip to the next header before reading
    std::mutex write_mutex_;
    bool broken_ = false;
};

}  // namespace kerf::lsp
