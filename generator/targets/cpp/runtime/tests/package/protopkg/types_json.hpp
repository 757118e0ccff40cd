// Stub package "protopkg" for the in-place runtime tests: the generated types_json.hpp holds
// Json<T> of the protocol's named types; the stub protocol has none.
#pragma once

#include "protopkg/json_codec.hpp"
