#!/usr/bin/env python3
"""Writes the seed corpus of fuzz_cache_entry (tests/fuzz/corpus/cache_entry/): entries of the
SPIR-V cache's format (gpu/shaders/spirv_cache.cpp) for the key the target looks up, well formed
and damaged. Run from the repository root; the fuzzers grow the corpus from there."""
import hashlib, os, struct

KEY = hashlib.sha256(b"lancer fuzz: the key looked up").digest()
FILES = {"main.comp": b'#version 450\n#include "a.glsl"\nvoid main() {}\n', "a.glsl": b"float a() { return 1.0; }\n"}
SPV, GLS = b"lancspv3", b"lancgls2"


def words(n, start=0x07230203):
    return b"".join(struct.pack("<I", (start + 977 * i) & 0xFFFFFFFF) for i in range(n))


def seal(head, body, checksum_at):
    entry = head + bytes(32) + body
    digest = hashlib.sha256(entry[:checksum_at] + entry[checksum_at + 32:]).digest()
    return entry[:checksum_at] + digest + entry[checksum_at + 32:]


def specialisation(payload, key=KEY, magic=SPV, count=None):
    count = len(payload) // 4 if count is None else count
    return seal(magic + key + struct.pack("<Q", count), payload, 48)


def compiled(manifest, payload, key=KEY, magic=GLS):
    return seal(magic + key + struct.pack("<QQ", len(manifest), len(payload) // 4), manifest + payload, 56)


def line(name):
    contents = FILES.get(name)
    return (hashlib.sha256(contents).hexdigest() if contents is not None else "-").encode() + b" " + name.encode() + b"\n"


good_manifest = line("a.glsl") + line("main.comp") + line("missing.glsl")
seeds = {
    # bit 0 of the first byte: 0 a specialisation, 1 a compile; bit 1: 0 raw, 2 sealed by the target
    "spv-good": b"\0" + specialisation(words(5)),
    "spv-good-large": b"\0" + specialisation(words(300)),
    "spv-bad-checksum": b"\0" + specialisation(words(5))[:-1] + b"\x5a",
    "spv-other-key": b"\0" + specialisation(words(5), key=hashlib.sha256(b"another").digest()),
    "spv-old-magic": b"\0" + specialisation(words(5), magic=b"lancspv2"),
    "spv-long-count": b"\0" + specialisation(words(5), count=6),
    "spv-huge-count": b"\0" + specialisation(words(5), count=1 << 40),
    "spv-zero-words": b"\0" + specialisation(b""),
    "spv-truncated": b"\0" + specialisation(words(5))[:60],
    "spv-header-only": b"\0" + specialisation(words(5))[:8],
    "empty": b"",
    "mode-only": b"\0",
    "spv-sealed": b"\2" + words(7),
    "spv-sealed-empty": b"\2",
    "gls-good": b"\1" + compiled(good_manifest, words(4)),
    "gls-no-manifest": b"\1" + compiled(b"", words(4)),
    "gls-stale-file": b"\1" + compiled(b"0" * 64 + b" a.glsl\n", words(4)),
    "gls-missing-now-present": b"\1" + compiled(b"- main.comp\n", words(4)),
    "gls-bad-checksum": b"\1" + compiled(good_manifest, words(4))[:-2] + b"\0\0",
    "gls-old-magic": b"\1" + compiled(good_manifest, words(4), magic=b"lancgls1"),
    "gls-truncated": b"\1" + compiled(good_manifest, words(4))[:100],
    "gls-sealed": b"\3" + struct.pack("<H", len(good_manifest)) + good_manifest + words(3),
    "gls-sealed-bad-line": b"\3" + struct.pack("<H", 12) + b"no-space-at\n" + words(3),
    "gls-sealed-empty-name": b"\3" + struct.pack("<H", 2) + b"- " + words(3),
    "gls-sealed-long-manifest-length": b"\3" + b"\xff\xff" + good_manifest,
}
out = "tests/fuzz/corpus/cache_entry"
os.makedirs(out, exist_ok=True)
for name, data in seeds.items():
    with open(os.path.join(out, name), "wb") as f:
        f.write(data)
print(f"{len(seeds)} seeds in {out}")
