#pragma once
// SHA-256 through OpenSSL's libcrypto (EVP): the collision-resistant hash that names and checks
// entries of lancer's on-disk caches, where a 64-bit hash could be made to collide on purpose.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace lancer {

using Sha256Digest = std::array<unsigned char, 32>;

// Incremental SHA-256. `add_field` frames its bytes with their length, so that consecutive
// fields cannot run into each other ("ab" + "c" and "a" + "bc" hash apart).
class Sha256 {
public:
    Sha256();
    ~Sha256();
    Sha256(const Sha256&) = delete;
    Sha256& operator=(const Sha256&) = delete;

    Sha256& add(const void* data, std::size_t size);
    Sha256& add(std::string_view bytes) { return add(bytes.data(), bytes.size()); }
    Sha256& add_u64(std::uint64_t value);  // little-endian, 8 bytes
    Sha256& add_field(const void* data, std::size_t size) { return add_u64(size).add(data, size); }
    Sha256& add_field(std::string_view bytes) { return add_field(bytes.data(), bytes.size()); }
    Sha256Digest finish();  // once; the object is spent afterwards

private:
    void* context_;  // EVP_MD_CTX
};

Sha256Digest sha256(const void* data, std::size_t size);
inline Sha256Digest sha256(std::string_view bytes) { return sha256(bytes.data(), bytes.size()); }

// Frees the calling thread's OpenSSL state now instead of at the thread's exit: a detached thread
// that reports itself finished (PipelineBuild) must hold nothing once it has, or a process that
// exits right after leaks it.
void release_thread_hash_state();

// Lower-case hexadecimal, 64 characters.
std::string to_hex(const Sha256Digest& digest);

}  // namespace lancer
