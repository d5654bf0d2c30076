#include "lsp/transport.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cctype>
#include <charconv>
#include <cstring>

#include <fmt/format.h>

namespace kerf::lsp {

namespace {

constexpr std::string_view kLengthHeader = "Content-Length:";

bool same_name(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// The bytes of `text` shown in a log line: at most 40, control bytes as '.'.
std::string shown(std::string_view text) {
    std::string out;
    for (const char c : text.substr(0, 40)) out += std::isprint(static_cast<unsigned char>(c)) ? c : '.';
    if (text.size() > 40) out += "...";
    return out;
}

}  // namespace

Transport::Transport(int in_fd, int out_fd) : in_(in_fd), out_(out_fd) {
    if (::pipe2(wake_, O_CLOEXEC) != 0) wake_[0] = wake_[1] = -1;
}

Transport::~Transport() {
    for (const int fd : wake_)
        if (fd >= 0) ::close(fd);
}

void Transport::interrupt() {
    if (wake_[1] >= 0) {
        const char byte = 1;
        [[maybe_unused]] const ssize_t n = ::write(wake_[1], &byte, 1);
    }
}

std::size_t Transport::read_some(char* into, std::size_t max) {
    if (eof_) return 0;
    if (wake_[0] >= 0) {
        pollfd fds[2] = {{in_, POLLIN, 0}, {wake_[0], POLLIN, 0}};
        while (true) {
            const int r = ::poll(fds, 2, -1);
            if (r < 0 && errno == EINTR) continue;
            if (r < 0 || (fds[1].revents & POLLIN)) {
                eof_ = true;
                return 0;
            }
            if (fds[0].revents) break;
        }
    }
    ssize_t n;
    do {
        n = ::read(in_, into, max);
    } while (n < 0 && errno == EINTR);
    if (n <= 0) eof_ = true;
    return static_cast<std::size_t>(std::max<ssize_t>(n, 0));
}

bool Transport::fill() {
    if (pos_ > 0 && pos_ * 2 >= buffer_.size()) {   // drop what was read before growing
        buffer_.erase(0, pos_);
        pos_ = 0;
    }
    const std::size_t old = buffer_.size();
    const std::size_t chunk = 1 << 20;
    buffer_.resize(old + chunk);
    const std::size_t n = read_some(buffer_.data() + old, chunk);
    buffer_.resize(old + n);
    return n > 0;
}

void Transport::unread(std::string_view bytes) {
    buffer_.erase(0, pos_);
    pos_ = 0;
    buffer_.insert(0, bytes);
}

// The next header line without its line end; nullopt at the end of the input.
std::optional<std::string> Transport::header_line(Frame& frame) {
    while (true) {
        const std::size_t nl = buffer_.find('\n', pos_);
        if (nl != std::string::npos) {
            std::string line = buffer_.substr(pos_, nl - pos_);
            pos_ = nl + 1;
            if (!line.empty() && line.back() == '\r') line.pop_back();
            return line;
        }
        if (buffer_.size() - pos_ > 8192) {   // no header is that long: this is not a header
            frame.problem = fmt::format("skipped bytes that are not a message header: '{}'", shown(std::string_view(buffer_).substr(pos_)));
            resync_pending_ = true;
            return std::nullopt;
        }
        if (!fill()) {
            if (pos_ < buffer_.size())
                frame.problem = fmt::format("the input ended inside a message header: '{}'", shown(std::string_view(buffer_).substr(pos_)));
            pos_ = buffer_.size();
            return std::nullopt;
        }
    }
}

// Skips to the next "Content-Length:" (the start of the next message, whatever came before).
void Transport::resync(Frame&) {
    while (true) {
        const std::size_t at = buffer_.find(kLengthHeader, pos_);
        if (at != std::string::npos) {
            pos_ = at;
            return;
        }
        // Keep a tail that may be the start of a header cut by the read.
        pos_ = std::max(pos_, buffer_.size() > kLengthHeader.size() ? buffer_.size() - kLengthHeader.size() : pos_);
        if (!fill()) {
            pos_ = buffer_.size();
            return;
        }
    }
}

std::optional<Frame> Transport::read() {
    Frame frame;
    // After a problem the bytes up to the next header are skipped now, not before the problem was
    // reported (the next message may be long in coming).
    if (resync_pending_) {
        resync_pending_ = false;
        resync(frame);
    }
    std::optional<std::size_t> length;
    bool any_header = false;
    while (true) {
        std::optional<std::string> line = header_line(frame);
        if (!line) {
            if (!frame.problem.empty()) return frame;   // reported now; the next read goes on or ends
            return std::nullopt;
        }
        if (line->empty()) {
            if (!any_header) continue;   // blank lines between messages
            break;
        }
        const std::size_t colon = line->find(':');
        const bool header_name = colon != std::string::npos && colon > 0 &&
                                 std::all_of(line->begin(), line->begin() + static_cast<std::ptrdiff_t>(colon),
                                             [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-'; });
        if (!header_name) {
            // Bytes that are not a header (the rest of a body cut short): skip them, up to a
            // header that may follow on the same line.
            const std::size_t next = line->find(kLengthHeader);
            frame.problem = fmt::format("skipped bytes that are not a message header: '{}'", shown(line->substr(0, next)));
            if (next != std::string::npos) unread(line->substr(next) + "\r\n");
            else resync_pending_ = true;
            return frame;
        }
        any_header = true;
        const std::string_view name = trim(std::string_view(*line).substr(0, colon));
        const std::string_view value = trim(std::string_view(*line).substr(colon + 1));
        if (!same_name(name, "Content-Length")) continue;   // Content-Type and others: nothing to do
        std::size_t n = 0;
        const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
        if (ec != std::errc() || end != value.data() + value.size()) {
            frame.problem = fmt::format("Content-Length '{}' is not a number; the message is skipped", shown(value));
            resync_pending_ = true;
            return frame;
        }
        length = n;
    }
    if (!length) {
        frame.problem = "a message header without Content-Length; the message is skipped";
        resync_pending_ = true;
        return frame;
    }
    if (*length > kMaxBody) {
        frame.problem = fmt::format("Content-Length {} is over the limit of {} bytes; the message is skipped", *length, kMaxBody);
        resync_pending_ = true;
        return frame;
    }
    // The body is read into its own string: a document of 50 MB is not copied out of the buffer,
    // and the buffer does not grow to hold it (bench/RESULTS.md, the server's memory).
    const std::size_t buffered = std::min(*length, buffer_.size() - pos_);
    frame.body.resize(*length);
    std::memcpy(frame.body.data(), buffer_.data() + pos_, buffered);
    pos_ += buffered;
    for (std::size_t have = buffered; have < *length;) {
        const std::size_t n = read_some(frame.body.data() + have, *length - have);
        if (n == 0) {
            frame.problem = fmt::format("the input ended inside a message ({} of {} bytes)", have, *length);
            frame.body.clear();
            return frame;
        }
        have += n;
    }
    return frame;
}

bool Transport::write(std::string_view body) {
    const std::string header = fmt::format("Content-Length: {}\r\n\r\n", body.size());
    const std::lock_guard lock(write_mutex_);
    if (broken_) return false;
    for (const std::string_view part : {std::string_view(header), body}) {
        for (std::size_t at = 0; at < part.size();) {
            const ssize_t n = ::write(out_, part.data() + at, part.size() - at);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                broken_ = true;
                return false;
            }
            at += static_cast<std::size_t>(n);
        }
    }
    return true;
}

}  // namespace kerf::lsp
