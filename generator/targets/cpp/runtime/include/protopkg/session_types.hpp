// The shapes of the command facts a package generates into session_facts.hpp (docs/conformance.md
// section 8): one CommandRow of constant integers per command layout, no allocation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace protopkg {

/// A reply field sent with the ack when its condition holds (spec `responses` with `when`).
struct ReplyRule {
    std::uint8_t descriptor;
    std::int16_t function; ///< the function selector value it needs, or -1
    std::int8_t param;     ///< slot of the parameter it needs (CommandTraits<T>::param), or -1
    bool has_value;        ///< the parameter must equal `value` (else: be non-zero)
    std::int64_t value;
};

/// What the spec says about one command layout.
struct CommandRow {
    std::uint8_t set;
    std::uint8_t descriptor;
    const char *name;
    std::int8_t device;       ///< the device whose layout this is (an index of kDevices), or -1
    std::uint32_t devices;    ///< bit i: kDevices[i] supports the command with this layout
    bool has_functions;       ///< the layout has a function selector
    std::uint64_t functions;  ///< bit v: function selector value v is accepted
    const ReplyRule *replies; ///< the reply rules (reply_count of them)
    std::uint8_t reply_count;
    std::uint8_t ack_kind; ///< 0: never suppressed, 1: by function `ack_value`, 2: by parameter `ack_param`
    std::int8_t ack_param; ///< parameter slot (ack_kind 2)
    bool ack_has_value;    ///< ack_kind 2: suppressed when the parameter equals ack_value (else non-zero)
    std::int64_t ack_value;
    bool has_timeout;           ///< the spec gives this command extra time
    std::uint32_t timeout_ms;   ///< fixed allowance
    std::int8_t timeout_param;  ///< parameter slot whose value (ms) adds to it, or -1
    bool timeout_all_functions; ///< the allowance holds for every function (else only timeout_functions)
    std::uint64_t timeout_functions;
};

/// Command facts of layout struct T: specialised for every command layout in session_facts.hpp
/// (kRow: its row of kCommandRows; function(v): its selector value or nullopt; param(v, slot): the
/// value of a parameter the row's rules name, nullopt when absent).
template <class T> struct CommandTraits {
    static constexpr bool kCommand = false;
};

/// The parameter slots a command layout's rules may name (the generator refuses more).
inline constexpr std::size_t kMaxParamSlots = 8;

/// What the session's rules read of one command value, computed once from its CommandTraits
/// (session.hpp command_facts) or from its field bytes (transport.cpp), so that the rules and the
/// connection's loop are plain functions, not one instance per command type.
struct CommandFacts {
    const CommandRow *row = nullptr;
    std::optional<std::int64_t> function;                             ///< its function selector value
    std::array<std::optional<std::int64_t>, kMaxParamSlots> params{}; ///< by slot
    std::optional<std::int64_t> param(std::int8_t slot) const {
        if (slot < 0 || static_cast<std::size_t>(slot) >= kMaxParamSlots) {
            return std::nullopt;
        }
        return params[static_cast<std::size_t>(slot)];
    }
};

} // namespace protopkg
