#include "scene/gltf/io/gltf_json_scan.h"

namespace wf::gltf {
namespace {

// A cursor over the text. Every method returns false on text that is not JSON; nothing past
// the buffers' members is validated, since tinygltf parses the whole document afterwards.
class Scanner {
public:
    explicit Scanner(std::string_view text) : text_(text) {
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") {
            at_ = 3; // nlohmann/json skips a UTF-8 byte order mark too
        }
    }

    bool atEnd() {
        skipSpace();
        return at_ == text_.size();
    }

    bool peek(char c) {
        skipSpace();
        return at_ < text_.size() && text_[at_] == c;
    }

    bool expect(char c) {
        if (!peek(c)) {
            return false;
        }
        ++at_;
        return true;
    }

    bool string(JsonSpan& span, bool& escaped) {
        if (!peek('"')) {
            return false;
        }
        span.begin = at_++;
        escaped = false;
        while (at_ < text_.size()) {
            const unsigned char c = static_cast<unsigned char>(text_[at_]);
            if (c == '\\') {
                escaped = true;
                at_ += 2;
            } else if (c == '"') {
                span.end = ++at_;
                return true;
            } else if (c < 0x20) {
                return false;
            } else {
                ++at_;
            }
        }
        return false;
    }

    // Skips one value of any kind; objects and arrays by bracket depth alone.
    bool value(JsonSpan& span) {
        skipSpace();
        if (at_ == text_.size()) {
            return false;
        }
        span.begin = at_;
        bool escaped = false;
        const char first = text_[at_];
        if (first == '"') {
            return string(span, escaped);
        }
        if (first == '{' || first == '[') {
            int depth = 0;
            while (at_ < text_.size()) {
                const char c = text_[at_];
                if (c == '"') {
                    JsonSpan inner;
                    if (!string(inner, escaped)) {
                        return false;
                    }
                    continue;
                }
                ++at_;
                depth += (c == '{' || c == '[') ? 1 : (c == '}' || c == ']') ? -1 : 0;
                if (depth == 0) {
                    span.end = at_;
                    return true;
                }
            }
            return false;
        }
        while (at_ < text_.size() && isScalarChar(text_[at_])) {
            ++at_;
        }
        span.end = at_;
        return span.present();
    }

    // Walks an object's members: onMember(key, keyEscaped) must consume the member's value.
    template <typename OnMember> bool object(OnMember&& onMember) {
        if (!expect('{')) {
            return false;
        }
        if (expect('}')) {
            return true;
        }
        do {
            JsonSpan key;
            bool escaped = false;
            if (!string(key, escaped) || !expect(':') || !onMember(key, escaped)) {
                return false;
            }
        } while (expect(','));
        return expect('}');
    }

    std::string_view text(JsonSpan span) const {
        return text_.substr(span.begin, span.end - span.begin);
    }

private:
    static bool isScalarChar(char c) {
        return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || c == '-' || c == '+' ||
               c == '.' || c == 'E';
    }

    void skipSpace() {
        while (at_ < text_.size() &&
               (text_[at_] == ' ' || text_[at_] == '\t' || text_[at_] == '\n' ||
                text_[at_] == '\r')) {
            ++at_;
        }
    }

    std::string_view text_;
    std::size_t at_ = 0;
};

bool scanBuffer(Scanner& in, BufferMembers& out) {
    return in.object([&](JsonSpan key, bool escaped) {
        if (escaped) {
            return false; // "\u0075ri" is "uri" to nlohmann
        }
        const std::string_view name = in.text(key);
        if (name == "\"uri\"") {
            if (out.uri.present()) {
                return false;
            }
            if (!in.peek('"')) {
                JsonSpan other; // not a string: tinygltf says so
                return in.value(other);
            }
            return in.string(out.uri, out.uriEscaped);
        }
        JsonSpan skipped;
        if (name == "\"byteLength\"") {
            if (out.byteLength.present()) {
                return false;
            }
            return in.value(out.byteLength);
        }
        return in.value(skipped);
    });
}

} // namespace

std::optional<std::vector<BufferMembers>> scanBufferMembers(std::string_view json) {
    Scanner in(json);
    std::vector<BufferMembers> buffers;
    bool seenBuffers = false;
    const bool scanned = in.object([&](JsonSpan key, bool escaped) {
        if (escaped) {
            return false;
        }
        if (in.text(key) != "\"buffers\"") {
            JsonSpan skipped;
            return in.value(skipped);
        }
        if (seenBuffers || !in.expect('[')) {
            return false;
        }
        seenBuffers = true;
        if (in.expect(']')) {
            return true;
        }
        do {
            BufferMembers& buffer = buffers.emplace_back();
            JsonSpan skipped;
            if (in.peek('{') ? !scanBuffer(in, buffer) : !in.value(skipped)) {
                return false;
            }
        } while (in.expect(','));
        return in.expect(']');
    });
    if (!scanned || !in.atEnd()) {
        return std::nullopt;
    }
    return buffers;
}

} // namespace wf::gltf
