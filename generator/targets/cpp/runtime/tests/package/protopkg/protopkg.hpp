// Stub package "protopkg" for the in-place runtime tests: everything, as the generated
// <pkg>.hpp (templates/cpp/include/package.hpp.j2) includes it.
#pragma once

#include "protopkg/checksum.hpp"
#include "protopkg/devices.hpp"
#include "protopkg/dispatch.hpp"
#include "protopkg/framing.hpp"
#include "protopkg/json_lines.hpp"
#include "protopkg/lookup.hpp"
#include "protopkg/packet.hpp"
#include "protopkg/parser.hpp"
#include "protopkg/samples.hpp"
#include "protopkg/wire.hpp"
