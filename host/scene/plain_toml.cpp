#include "scene/plain_toml.hpp"

#include <cfloat>
#include <charconv>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>

// It follows toml++ 3.3's parser (Debian 12's) to the column; PlainToml.* and the scene fuzz target
// compare its trees with the installed toml::parse's, so another version's differences show there.
namespace lancer {
namespace plain {  // its own: the unity build shares anonymous namespaces among files
namespace {

// toml::node keeps its source region private for its parser (a friend) to set; an explicit
// instantiation may name a private member, which lets this reader set the regions the parser would.
using SourceMember = toml::source_region toml::node::*;
SourceMember node_source();
template <SourceMember Member>
struct NodeSourceGrant {
    friend SourceMember node_source() { return Member; }
};
template struct NodeSourceGrant<&toml::node::source_>;

using NodePtr = toml::impl::node_ptr;

// Thrown at anything that is not plain TOML; parse_plain_toml answers nullopt.
struct NotPlain {};

// Deeper values, longer numbers and longer header keys are left to toml::parse (its own limits:
// 256 nested values, 127 characters a number).
constexpr int kMaxDepth = 64;
constexpr std::size_t kMaxNumberLength = 64;
constexpr int kMaxHeaderKeys = 4;
// Decimal integers of up to 18 digits fit an int64 whatever their digits.
constexpr std::size_t kMaxIntegerDigits = 18;

bool is_bare_key_char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// What strings and comments may hold here: printable ASCII and tab (toml::parse refuses other
// control characters; other bytes are UTF-8, whose columns count code points).
bool is_plain_text_char(char c) {
    const auto u = static_cast<unsigned char>(c);
    return c == '\t' || (u >= 0x20 && u < 0x7F);
}

// What toml::parse takes to end a number or a word (true, inf): whitespace, a bracket, a comma,
// a comment (\v and \f too, which are errors later and so not plain).
bool ends_value(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',' || c == ']' || c == '}' || c == '#';
}

// toml::parse's array of tables ([[a]]) holds tables that are not inline, never none; an array
// value's tables are inline. The parser keeps a list of the former; here the array tells.
bool is_table_array(const toml::array& a) {
    return !a.empty() && a.front().is_table() && !a.front().as_table()->is_inline();
}

template <class T>
NodePtr make_value(T v) {
    return NodePtr(new toml::value<T>(std::move(v)));
}

class PlainReader {
public:
    PlainReader(std::string_view text, std::string_view path)
        : text_(text), path_(path.empty() ? nullptr : std::make_shared<const std::string>(path)) {}

    toml::table document();

private:
    struct Key {
        std::string_view name;
        toml::source_position begin, end;
    };
    // The items of an array or inline table, their opening bracket next: `item(c)` reads one that
    // starts with c. An array's may be on several lines, with comments, and a comma may end it.
    enum class List { Array, InlineTable };
    template <class ReadItem>
    void comma_separated(List list, ReadItem item);

    [[noreturn]] static void decline() { throw NotPlain{}; }
    bool done() const { return at_ >= text_.size(); }
    char peek(std::size_t ahead = 0) const { return at_ + ahead < text_.size() ? text_[at_ + ahead] : '\0'; }
    toml::source_position position() const {
        return {line_, static_cast<toml::source_index>(at_ - line_start_ + 1)};
    }
    void set_source(toml::node& n, toml::source_position begin, toml::source_position end) const {
        n.*node_source() = toml::source_region{begin, end, path_};
    }

    void skip_blanks() {
        while (peek() == ' ' || peek() == '\t') ++at_;
    }
    void line_break();
    void comment();
    void skip_blank_lines();
    void end_of_line();
    Key bare_key();
    toml::table* header(toml::table& root);
    void key_value(toml::table& table);
    NodePtr value();
    NodePtr basic_string();
    NodePtr literal_string();
    NodePtr boolean();
    NodePtr number();
    NodePtr array();
    NodePtr inline_table();
    void expect_value_end() const {
        if (!done() && !ends_value(peek())) decline();
    }

    std::string_view text_;
    std::shared_ptr<const std::string> path_;  // shared by every node, as toml::parse's
    std::size_t at_ = 0;
    std::size_t line_start_ = 0;
    toml::source_index line_ = 1;
    toml::source_position last_line_break_{};
    int depth_ = 0;
};

toml::table PlainReader::document() {
    toml::table root;
    toml::table* current = &root;
    for (skip_blank_lines(); !done(); skip_blank_lines()) {
        const char c = peek();
        if (c == '[') {
            current = header(root);
        } else if (is_bare_key_char(c)) {
            key_value(*current);
            end_of_line();
        } else {
            decline();
        }
    }
    // toml::parse ends the document a column past its last character.
    toml::source_position end{1, 1};
    if (!text_.empty()) end = text_.back() == '\n' ? toml::source_position{last_line_break_.line, last_line_break_.column + 1} : position();
    set_source(root, {1, 1}, end);
    return root;
}

// Blanks, line breaks and comments, up to the next thing of substance (or the end).
void PlainReader::skip_blank_lines() {
    while (true) {
        const char c = peek();
        if (c == ' ' || c == '\t') {
            ++at_;
        } else if (c == '\n' || c == '\r') {
            line_break();
        } else if (c == '#') {
            comment();
        } else {
            return;
        }
    }
}

// At '\n' or "\r\n".
void PlainReader::line_break() {
    if (peek() == '\r') {
        ++at_;
        if (peek() != '\n') decline();
    }
    last_line_break_ = position();
    ++at_;
    ++line_;
    line_start_ = at_;
}

// From '#' through the line break.
void PlainReader::comment() {
    ++at_;
    while (!done()) {
        const char c = peek();
        if (c == '\n' || c == '\r') return line_break();
        if (!is_plain_text_char(c)) decline();
        ++at_;
    }
}

// After a header or a key's value: blanks, then a comment, a line break or the end.
void PlainReader::end_of_line() {
    skip_blanks();
    if (done()) return;
    if (peek() == '#') return comment();
    if (peek() == '\n' || peek() == '\r') return line_break();
    decline();
}

PlainReader::Key PlainReader::bare_key() {
    Key key;
    key.begin = position();
    const std::size_t from = at_;
    while (is_bare_key_char(peek())) ++at_;
    if (at_ == from) decline();
    key.name = text_.substr(from, at_ - from);
    key.end = position();
    return key;
}

// [a.b] or [[a.b]] through its line's end; the table that the following keys go to. Parents
// must exist: toml::parse would make implicit tables, whose rules are not plain.
toml::table* PlainReader::header(toml::table& root) {
    const toml::source_position begin = position();
    ++at_;
    const bool is_array = peek() == '[';
    if (is_array) ++at_;
    skip_blanks();
    Key keys[kMaxHeaderKeys];
    int count = 0;
    while (true) {
        if (count == kMaxHeaderKeys) decline();
        keys[count++] = bare_key();
        skip_blanks();
        if (peek() != '.') break;
        ++at_;
        skip_blanks();
    }
    if (peek() != ']') decline();
    ++at_;
    if (is_array) {
        if (peek() != ']') decline();
        ++at_;
    }
    const toml::source_position end = position();
    end_of_line();

    toml::table* parent = &root;
    for (int i = 0; i + 1 < count; ++i) {
        const auto found = parent->find(keys[i].name);
        if (found == parent->end()) decline();
        toml::node& node = found->second;
        if (toml::table* t = node.as_table(); t && !t->is_inline()) {
            parent = t;
        } else if (toml::array* a = node.as_array(); a && is_table_array(*a)) {
            parent = a->back().as_table();  // the array's latest table, as TOML says
        } else {
            decline();
        }
    }

    const Key& last = keys[count - 1];
    auto it = parent->lower_bound(last.name);
    if (it != parent->end() && it->first == last.name) {
        toml::array* a = it->second.as_array();
        if (!is_array || !a || !is_table_array(*a)) decline();  // redefined: toml::parse says so
        toml::table& table = a->emplace_back<toml::table>();
        set_source(table, begin, end);
        // toml::parse ends an array of tables where its last header ends.
        ((*a).*node_source()).end = end;
        return &table;
    }
    toml::key key(last.name, toml::source_region{last.begin, last.end, path_});
    if (!is_array) {
        it = parent->emplace_hint<toml::table>(it, std::move(key));
        toml::table& table = *it->second.as_table();
        set_source(table, begin, end);
        return &table;
    }
    it = parent->emplace_hint<toml::array>(it, std::move(key));
    toml::array& a = *it->second.as_array();
    set_source(a, begin, end);
    toml::table& table = a.emplace_back<toml::table>();
    set_source(table, begin, end);
    return &table;
}

// key = value, in `table`; a key already there is an error for toml::parse to report.
void PlainReader::key_value(toml::table& table) {
    const Key key = bare_key();
    skip_blanks();
    if (peek() != '=') decline();  // a dotted key among others
    ++at_;
    skip_blanks();
    const auto it = table.lower_bound(key.name);
    if (it != table.end() && it->first == key.name) decline();
    NodePtr v = value();
    table.emplace_hint<NodePtr>(it, toml::key(key.name, toml::source_region{key.begin, key.end, path_}), std::move(v));
}

NodePtr PlainReader::value() {
    if (++depth_ > kMaxDepth) decline();
    const toml::source_position begin = position();
    NodePtr v;
    switch (peek()) {
        case '"': v = basic_string(); break;
        case '\'': v = literal_string(); break;
        case '[': v = array(); break;
        case '{': v = inline_table(); break;
        case 't':
        case 'f': v = boolean(); break;
        default: v = number(); break;
    }
    set_source(*v, begin, position());
    --depth_;
    return v;
}

// "..." on one line, with the escapes that stand for one ASCII character.
NodePtr PlainReader::basic_string() {
    ++at_;
    if (peek() == '"' && peek(1) == '"') decline();  // """ opens a multi-line string
    std::string s;
    std::size_t run = at_;  // the start of the characters not yet appended
    while (true) {
        if (done()) decline();
        const char c = peek();
        if (c == '"') break;
        if (c == '\\') {
            s.append(text_.substr(run, at_ - run));
            ++at_;
            switch (peek()) {
                case 'b': s += '\b'; break;
                case 't': s += '\t'; break;
                case 'n': s += '\n'; break;
                case 'f': s += '\f'; break;
                case 'r': s += '\r'; break;
                case '"': s += '"'; break;
                case '\\': s += '\\'; break;
                default: decline();  // \u, \U, or an error
            }
            ++at_;
            run = at_;
            continue;
        }
        if (!is_plain_text_char(c)) decline();
        ++at_;
    }
    s.append(text_.substr(run, at_ - run));
    ++at_;
    return make_value(std::move(s));
}

// '...' on one line.
NodePtr PlainReader::literal_string() {
    ++at_;
    if (peek() == '\'' && peek(1) == '\'') decline();  // ''' opens a multi-line string
    const std::size_t from = at_;
    while (peek() != '\'') {
        if (!is_plain_text_char(peek())) decline();  // the end included
        ++at_;
    }
    std::string s(text_.substr(from, at_ - from));
    ++at_;
    return make_value(std::move(s));
}

NodePtr PlainReader::boolean() {
    const std::string_view rest = text_.substr(at_);
    bool b;
    if (rest.substr(0, 4) == "true") {
        b = true;
        at_ += 4;
    } else if (rest.substr(0, 5) == "false") {
        b = false;
        at_ += 5;
    } else {
        decline();
    }
    expect_value_end();
    return make_value(b);
}

// [+-] then inf or nan, or 0 or digits without a leading 0, [. digits], [e [+-] digits]: a float
// where it has a fraction or an exponent, an integer otherwise, as toml::parse reads them.
NodePtr PlainReader::number() {
    const std::size_t start = at_;
    const bool negative = peek() == '-';
    if (peek() == '+' || peek() == '-') ++at_;
    const std::string_view rest = text_.substr(at_);
    if (rest.substr(0, 3) == "inf" || rest.substr(0, 3) == "nan") {
        at_ += 3;
        expect_value_end();
        // toml::parse gives -inf, but nan whatever its sign.
        if (rest[0] == 'n') return make_value(std::numeric_limits<double>::quiet_NaN());
        return make_value(negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity());
    }
    const std::size_t digits = at_;
    if (peek() == '0') {
        ++at_;
    } else if (is_digit(peek())) {
        while (is_digit(peek())) ++at_;
    } else {
        decline();
    }
    bool is_float = false;
    if (peek() == '.') {
        ++at_;
        if (!is_digit(peek())) decline();
        while (is_digit(peek())) ++at_;
        is_float = true;
    }
    if (peek() == 'e' || peek() == 'E') {
        ++at_;
        if (peek() == '+' || peek() == '-') ++at_;
        if (!is_digit(peek())) decline();
        while (is_digit(peek())) ++at_;
        is_float = true;
    }
    expect_value_end();  // also where 0 had more digits, or an underscore came
    if (at_ - start > kMaxNumberLength) decline();
    const std::string_view magnitude = text_.substr(digits, at_ - digits);
    if (!is_float) {
        if (magnitude.size() > kMaxIntegerDigits) decline();
        std::int64_t n = 0;
        for (char c : magnitude) n = n * 10 + (c - '0');
        return make_value(negative ? -n : n);
    }
    // Correctly rounded, as the strtod behind toml::parse's stream; it refuses what overflows or
    // underflows to 0, which toml::parse refuses or may read otherwise. Subnormals likewise.
    double x = 0.0;
    const char* const end = magnitude.data() + magnitude.size();
    const auto [stop, error] = std::from_chars(magnitude.data(), end, x);
    if (error != std::errc{} || stop != end || (x != 0.0 && x < DBL_MIN)) decline();
    return make_value(negative ? -1 * x : x);  // toml::parse multiplies by the sign: -0.0 stays
}

template <class ReadItem>
void PlainReader::comma_separated(List list, ReadItem item) {
    const char close = list == List::Array ? ']' : '}';
    enum class Last { Nothing, Comma, Item } last = Last::Nothing;
    ++at_;
    while (true) {
        list == List::Array ? skip_blank_lines() : skip_blanks();
        if (done()) decline();
        const char c = peek();
        if (c == ',') {
            if (last != Last::Item) decline();
            last = Last::Comma;
            ++at_;
        } else if (c == close) {
            if (last == Last::Comma && list == List::InlineTable) decline();  // TOML 1.0: none in an inline table
            ++at_;
            return;
        } else {
            if (last == Last::Item) decline();
            item(c);
            last = Last::Item;
        }
    }
}

// [values, ...]
NodePtr PlainReader::array() {
    auto a = std::make_unique<toml::array>();
    comma_separated(List::Array, [&](char) {
        if (a->empty()) a->reserve(4);  // as toml::parse: an array's first four values, one allocation
        a->emplace_back<NodePtr>(value());
    });
    return a;
}

// { key = value, ... } on one line.
NodePtr PlainReader::inline_table() {
    auto table = std::make_unique<toml::table>();
    table->is_inline(true);
    comma_separated(List::InlineTable, [&](char c) {
        if (!is_bare_key_char(c)) decline();
        key_value(*table);
    });
    return table;
}

}  // namespace
}  // namespace plain

std::optional<toml::table> parse_plain_toml(std::string_view text, std::string_view path) {
    try {
        return plain::PlainReader(text, path).document();
    } catch (const plain::NotPlain&) {
        return std::nullopt;
    }
}

}  // namespace lancer
