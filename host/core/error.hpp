#pragma once
// lancer's error values. Everything a user can cause (a wrong scene, a bad option, an unwritable
// output, a machine without a Vulkan device) is a UserError and exits with code 2; anything else
// that escapes is an internal failure (exit code 1). The CLI turns both into one message.
#include <memory>
#include <stdexcept>
#include <string>

namespace lancer {

// A file's name, shared by the copies of it (a million objects read from one file hold one
// string), read as a const std::string.
class FileName {
public:
    FileName() = default;
    FileName(std::string name) : name_(std::make_shared<const std::string>(std::move(name))) {}
    FileName(const char* name) : FileName(std::string(name)) {}

    const std::string& str() const { return name_ ? *name_ : empty_name(); }
    operator const std::string&() const { return str(); }
    bool empty() const { return str().empty(); }
    const char* c_str() const { return str().c_str(); }
    friend bool operator==(const FileName& a, const FileName& b) { return a.str() == b.str(); }

private:
    static const std::string& empty_name() {
        static const std::string empty;
        return empty;
    }
    std::shared_ptr<const std::string> name_;
};

// Where in a text file something is. line and column are 1-based; 0 means "unknown".
struct SourceLocation {
    FileName file;
    int line = 0;
    int column = 0;
};

class UserError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A message of several lines on purpose (a shader compiler's log): format_error keeps its line
// breaks, where in any other message a line break can only come from a name and is escaped.
class MultiLineUserError : public UserError {
public:
    using UserError::UserError;
};

// A problem in an input file, reported as "file:line:col: error: message".
class SceneError : public UserError {
public:
    SceneError(SourceLocation where, const std::string& message)
        : UserError(message), where_(std::move(where)) {}
    const SourceLocation& where() const { return where_; }

private:
    SourceLocation where_;
};

// The one rendering of an error for humans: "file:line:col: error: what" (or "lancer: error: what"),
// with control characters in names (the file's, or those in the message) escaped.
std::string format_error(const std::exception& e);
// format_error's line on stderr: what every command prints for an error it does not stop on.
void print_error(const std::exception& e);

}  // namespace lancer
