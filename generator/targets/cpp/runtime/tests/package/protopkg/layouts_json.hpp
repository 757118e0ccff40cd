// Stub package "protopkg" for the in-place runtime tests: hand-written in the shape of the
// generated fields/<set>_json.hpp (templates/cpp/include/fields_json.hpp.j2), gathered as the
// generated layouts_json.hpp gathers them.
#pragma once

#include "protopkg/fields.hpp"
#include "protopkg/json_codec.hpp"
#include "protopkg/types_json.hpp"

namespace protopkg {

template <> struct Json<stub::Ping> {
    static void write(JsonWriter &w, const stub::Ping &v) {
        w.begin_object();
        w.key("value");
        json_write_value(w, v.value);
        w.key("flags");
        json_write_value(w, v.flags);
        w.end_object();
    }
    static bool read(const json::Value &in, stub::Ping &v, JsonError &err) {
        if (!json_check_object(in, {"value", "flags"}, err)) {
            return false;
        }
        const json::Value *value = in.find("value");
        if (value == nullptr) {
            return err.missing("value");
        }
        if (!json_read_value(*value, v.value, err)) {
            err.enter("value");
            return false;
        }
        const json::Value *flags = in.find("flags");
        if (flags == nullptr) {
            return err.missing("flags");
        }
        if (!json_read_value(*flags, v.flags, err)) {
            err.enter("flags");
            return false;
        }
        return true;
    }
};

template <> struct Json<stub::InfoGx> {
    static void write(JsonWriter &w, const stub::InfoGx &v) {
        w.begin_object();
        w.key("level");
        json_write_value(w, v.level);
        w.end_object();
    }
    static bool read(const json::Value &in, stub::InfoGx &v, JsonError &err) {
        if (!json_check_object(in, {"level"}, err)) {
            return false;
        }
        const json::Value *level = in.find("level");
        if (level == nullptr) {
            return err.missing("level");
        }
        if (!json_read_value(*level, v.level, err)) {
            err.enter("level");
            return false;
        }
        return true;
    }
};

template <> struct Json<stub::InfoCv> {
    static void write(JsonWriter &w, const stub::InfoCv &v) {
        w.begin_object();
        w.key("level");
        json_write_value(w, v.level);
        w.key("offset");
        json_write_value(w, v.offset);
        w.end_object();
    }
    static bool read(const json::Value &in, stub::InfoCv &v, JsonError &err) {
        if (!json_check_object(in, {"level", "offset"}, err)) {
            return false;
        }
        const json::Value *level = in.find("level");
        if (level == nullptr) {
            return err.missing("level");
        }
        if (!json_read_value(*level, v.level, err)) {
            err.enter("level");
            return false;
        }
        const json::Value *offset = in.find("offset");
        if (offset == nullptr) {
            return err.missing("offset");
        }
        if (!json_read_value(*offset, v.offset, err)) {
            err.enter("offset");
            return false;
        }
        return true;
    }
};

template <> struct Json<stub::Switch> {
    static void write(JsonWriter &w, const stub::Switch &v) {
        w.begin_object();
        w.key("on");
        json_write_value(w, v.on);
        w.end_object();
    }
    static bool read(const json::Value &in, stub::Switch &v, JsonError &err) {
        if (!json_check_object(in, {"on"}, err)) {
            return false;
        }
        const json::Value *on = in.find("on");
        if (on == nullptr) {
            return err.missing("on");
        }
        if (!json_read_value(*on, v.on, err)) {
            err.enter("on");
            return false;
        }
        return true;
    }
};

} // namespace protopkg
