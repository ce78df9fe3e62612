#include "scene/object_batches.hpp"

#include <algorithm>

namespace lancer {
namespace {

bool is_bare_key_char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

// A table header's first key, and whether it is the whole key of an array of tables' header.
struct Header {
    std::string_view first_key;
    bool array = false;
    bool only_key = false;
};

// Walks TOML text line by line. Each method starts at the start of a line, or inside one as
// said, and returns false (or nullopt) at anything it is not sure of.
class Scanner {
public:
    explicit Scanner(std::string_view text) : text_(text) {}

    bool done() const { return at_ >= text_.size(); }
    std::size_t at() const { return at_; }
    int line() const { return line_; }
    char peek(std::size_t ahead = 0) const { return at_ + ahead < text_.size() ? text_[at_ + ahead] : '\0'; }

    void skip_blanks() {
        while (peek() == ' ' || peek() == '\t') ++at_;
    }

    // A bare first key (a quoted one could spell "object": nullopt); the scanner stays before it.
    std::optional<std::string_view> first_key() const {
        std::size_t end = at_;
        while (end < text_.size() && is_bare_key_char(text_[end])) ++end;
        if (end == at_) return std::nullopt;
        return text_.substr(at_, end - at_);
    }

    // A header line, from its '[' through its line break.
    std::optional<Header> header() {
        Header h;
        ++at_;
        if (peek() == '[') {
            h.array = true;
            ++at_;
        }
        skip_blanks();
        const auto key = first_key();
        if (!key) return std::nullopt;
        h.first_key = *key;
        at_ += key->size();
        skip_blanks();
        h.only_key = peek() == ']';
        while (peek() != ']') {
            const char c = peek();
            if (c == '"' || c == '\'') {
                if (!single_line_string()) return std::nullopt;
            } else if (c == '\0' || c == '\n' || c == '#' || c == '[') {
                return std::nullopt;
            } else {
                ++at_;
            }
        }
        ++at_;
        if (h.array && peek() != ']') return std::nullopt;
        if (h.array) ++at_;
        skip_blanks();
        if (peek() == '#') skip_comment();
        if (peek() == '\r') ++at_;
        if (!done() && peek() != '\n') return std::nullopt;
        next_line();
        return h;
    }

    // A key/value line, a comment or a blank line, through the line break that ends it outside
    // every string and bracket (a value may span lines: a multi-line string or array).
    bool statement() {
        int depth = 0;
        while (!done()) {
            const char c = peek();
            if (c == '\n') {
                next_line();
                if (depth == 0) return true;
            } else if (c == '#') {
                skip_comment();
            } else if (c == '"' || c == '\'') {
                const bool multi_line = peek(1) == c && peek(2) == c;
                if (!(multi_line ? multi_line_string() : single_line_string())) return false;
            } else {
                if (c == '[' || c == '{') ++depth;
                if ((c == ']' || c == '}') && --depth < 0) return false;
                ++at_;
            }
        }
        return depth == 0;
    }

private:
    void next_line() {
        ++at_;
        ++line_;
    }

    void skip_comment() {
        while (!done() && peek() != '\n') ++at_;
    }

    // "..." with escapes, or '...'; neither may hold a line break.
    bool single_line_string() {
        const char quote = peek();
        ++at_;
        while (!done() && peek() != quote) {
            if (quote == '"' && peek() == '\\') ++at_;
            if (peek() == '\n') return false;
            ++at_;
        }
        if (done()) return false;
        ++at_;
        return true;
    }

    // """...""" with escapes, or '''...''': it ends at three quotes, and up to two more just
    // before them are its own.
    bool multi_line_string() {
        const char quote = peek();
        at_ += 3;
        while (!done()) {
            const char c = peek();
            if (c == '\n') {
                next_line();
            } else if (quote == '"' && c == '\\') {
                at_ += 1;
                if (peek() == '\n') next_line();
                else ++at_;
            } else if (c == quote) {
                std::size_t run = 0;
                while (peek() == quote) {
                    ++at_;
                    ++run;
                }
                if (run >= 3) return run <= 5;
            } else {
                ++at_;
            }
        }
        return false;
    }

    std::string_view text_;
    std::size_t at_ = 0;
    int line_ = 1;
};

// The text without the batches' bytes but their line breaks.
std::string blank_batches(std::string_view text, const std::vector<ObjectBatch>& batches) {
    std::string head;
    std::size_t from = 0;
    for (const ObjectBatch& b : batches) {
        head.append(text.substr(from, b.begin - from));
        const std::string_view batch = text.substr(b.begin, b.end - b.begin);
        head.append(static_cast<std::size_t>(std::count(batch.begin(), batch.end(), '\n')), '\n');
        from = b.end;
    }
    head.append(text.substr(from));
    return head;
}

}  // namespace

std::optional<SceneTextParts> split_object_tables(std::string_view text, std::size_t per_batch) {
    enum class Region { Root, Table, Object };  // where the current line's keys go
    Region region = Region::Root;
    SceneTextParts parts;
    std::optional<ObjectBatch> open;
    const auto close = [&](std::size_t end) {
        if (!open) return;
        open->end = end;
        parts.batches.push_back(*open);
        open.reset();
    };
    Scanner s(text);
    while (!s.done()) {
        const std::size_t line_start = s.at();
        const int line = s.line();
        s.skip_blanks();
        if (s.peek() != '[') {
            const bool key = s.peek() != '#' && s.peek() != '\n' && s.peek() != '\r';
            if (key && region == Region::Root && s.first_key().value_or("object") == "object") return std::nullopt;
            if (!s.statement()) return std::nullopt;
            continue;
        }
        const std::optional<Header> header = s.header();
        if (!header) return std::nullopt;
        if (header->first_key != "object") {
            close(line_start);
            region = Region::Table;
        } else if (header->array && header->only_key) {
            if (open && open->objects == per_batch) close(line_start);
            if (!open) open = ObjectBatch{line_start, 0, line, 0};
            ++open->objects;
            ++parts.objects;
            region = Region::Object;
        } else if (region != Region::Object) {
            return std::nullopt;  // [object] or an object's sub-table where the last header is not an object's
        }
    }
    close(text.size());
    if (parts.batches.empty()) return std::nullopt;
    parts.head = blank_batches(text, parts.batches);
    return parts;
}

}  // namespace lancer
