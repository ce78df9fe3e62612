#include "core/sha256.hpp"

#include <stdexcept>

#include <openssl/crypto.h>
#include <openssl/evp.h>

namespace lancer {
namespace {

[[noreturn]] void fail(const char* what) { throw std::runtime_error(std::string("SHA-256 (OpenSSL): ") + what + " failed"); }

EVP_MD_CTX* ctx(void* p) { return static_cast<EVP_MD_CTX*>(p); }

}  // namespace

Sha256::Sha256() : context_(EVP_MD_CTX_new()) {
    if (!context_) fail("EVP_MD_CTX_new");
    if (EVP_DigestInit_ex(ctx(context_), EVP_sha256(), nullptr) != 1) {
        EVP_MD_CTX_free(ctx(context_));
        fail("EVP_DigestInit_ex");
    }
}

Sha256::~Sha256() { EVP_MD_CTX_free(ctx(context_)); }

Sha256& Sha256::add(const void* data, std::size_t size) {
    if (size && EVP_DigestUpdate(ctx(context_), data, size) != 1) fail("EVP_DigestUpdate");
    return *this;
}

Sha256& Sha256::add_u64(std::uint64_t value) {
    unsigned char bytes[8];
    for (int i = 0; i < 8; ++i) bytes[i] = static_cast<unsigned char>(value >> (8 * i));
    return add(bytes, sizeof bytes);
}

Sha256Digest Sha256::finish() {
    Sha256Digest digest{};
    unsigned int size = 0;
    if (EVP_DigestFinal_ex(ctx(context_), digest.data(), &size) != 1 || size != digest.size()) fail("EVP_DigestFinal_ex");
    return digest;
}

Sha256Digest sha256(const void* data, std::size_t size) {
    Sha256Digest digest{};
    unsigned int length = 0;
    if (EVP_Digest(data, size, digest.data(), &length, EVP_sha256(), nullptr) != 1 || length != digest.size())
        fail("EVP_Digest");
    return digest;
}

void release_thread_hash_state() { OPENSSL_thread_stop(); }

std::string to_hex(const Sha256Digest& digest) {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string hex;
    hex.reserve(2 * digest.size());
    for (unsigned char b : digest) {
        hex += kDigits[b >> 4];
        hex += kDigits[b & 15];
    }
    return hex;
}

}  // namespace lancer
