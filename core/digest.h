#pragma once
/// \file digest.h
/// \brief Content digests: job keys, series keys, campaign identities.
#include <string>

namespace beverloo {

/// SHA-256 of the bytes, as 64 lowercase hex digits (OpenSSL libcrypto).
std::string sha256_hex(const std::string& bytes);

}  // namespace beverloo
