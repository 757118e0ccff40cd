//! 3DM Command Set. Device configuration common to MicroStrain inertial sensors.
//!
//! Descriptor set 0x0C (command set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x0C;

/// Event control. Enable, disable or test an event trigger.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Trigger instance; 0 applies to all configured triggers (not for read). Sent for: write, read, save, load, default.
    pub instance: u8,
    /// How to change the trigger state. Sent for: write.
    pub mode: Option<crate::types::EventControlMode>,
}

impl Default for EventControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EventControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        instance: <u8 as crate::wire::Wire>::ZERO,
        mode: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_instance = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("instance"))?;
        let p_mode = if r.left() > 0 {
            Some(
                <crate::types::EventControlMode as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("mode"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            instance: p_instance,
            mode: p_mode,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.instance;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("instance"))?;
        if let Some(v) = &self.mode {
            optionals.present("mode")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("mode"))?;
        } else {
            optionals.absent("mode");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.instance;
        crate::json::key(w, &mut first, "instance")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.mode {
            crate::json::key(w, &mut first, "mode")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EventControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "instance", "mode"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_instance = o.req("instance", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_mode = o.opt(
            "mode",
            <crate::types::EventControlMode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            instance: p_instance,
            mode: p_mode,
        })
    }
}

impl EventControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for EventControl {
    const DESCRIPTOR: u8 = 0x2B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "event_control";
}

/// Event control (response). Current mode of a trigger.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventControlResponse {
    /// Trigger instance.
    pub instance: u8,
    /// Trigger mode.
    pub mode: crate::types::EventControlMode,
}

impl Default for EventControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EventControlResponse {
    const ZERO: Self = Self {
        instance: <u8 as crate::wire::Wire>::ZERO,
        mode: <crate::types::EventControlMode as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_instance = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("instance"))?;
        let p_mode = <crate::types::EventControlMode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("mode"))?;
        Ok(Self {
            instance: p_instance,
            mode: p_mode,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.instance;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("instance"))?;
        let v = &self.mode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mode"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.instance;
        crate::json::key(w, &mut first, "instance")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.mode;
        crate::json::key(w, &mut first, "mode")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EventControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["instance", "mode"])?;
        let p_instance = o.req("instance", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_mode = o.req(
            "mode",
            <crate::types::EventControlMode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            instance: p_instance,
            mode: p_mode,
        })
    }
}

impl EventControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for EventControlResponse {
    const DESCRIPTOR: u8 = 0xB5;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "event_control_response";
}

/// Get event trigger status. Report the type and status of event triggers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetEventTriggerStatus {
    /// Number of entries requested; 0 requests all trigger slots.
    pub requested_count: u8,
    /// Trigger instances to query.
    pub requested_instances: crate::bounded::BoundedVec<u8, 252>,
}

impl Default for GetEventTriggerStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetEventTriggerStatus {
    const ZERO: Self = Self {
        requested_count: <u8 as crate::wire::Wire>::ZERO,
        requested_instances: <crate::bounded::BoundedVec<u8, 252> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_requested_count =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("requested_count"))?;
        let p_requested_instances =
            crate::bounded::BoundedVec::<u8, 252>::decode_counted(r, u64::from(p_requested_count))
                .map_err(|e| e.at("requested_instances"))?;
        Ok(Self {
            requested_count: p_requested_count,
            requested_instances: p_requested_instances,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.requested_count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("requested_count"))?;
        let v = &self.requested_instances;
        v.encode_counted(w, u64::from(self.requested_count))
            .map_err(|e| e.at("requested_instances"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.requested_count;
        crate::json::key(w, &mut first, "requested_count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.requested_instances;
        crate::json::key(w, &mut first, "requested_instances")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GetEventTriggerStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["requested_count", "requested_instances"])?;
        let p_requested_count = o.req(
            "requested_count",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_requested_instances = o.req(
            "requested_instances",
            <crate::bounded::BoundedVec<u8, 252> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            requested_count: p_requested_count,
            requested_instances: p_requested_instances,
        })
    }
}

impl GetEventTriggerStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GetEventTriggerStatus {
    const DESCRIPTOR: u8 = 0x2C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "get_event_trigger_status";
}

/// Event trigger status. Status of the requested triggers, in the order requested (increasing if all).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventTriggerStatus {
    /// Number of entries.
    pub count: u8,
    /// The configured triggers.
    pub triggers: crate::bounded::BoundedVec<crate::types::TriggerStatusEntry, 126>,
}

impl Default for EventTriggerStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EventTriggerStatus {
    const ZERO: Self = Self {
        count: <u8 as crate::wire::Wire>::ZERO,
        triggers: <crate::bounded::BoundedVec<crate::types::TriggerStatusEntry, 126> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        let p_triggers =
            crate::bounded::BoundedVec::<crate::types::TriggerStatusEntry, 126>::decode_counted(
                r,
                u64::from(p_count),
            )
            .map_err(|e| e.at("triggers"))?;
        Ok(Self {
            count: p_count,
            triggers: p_triggers,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        let v = &self.triggers;
        v.encode_counted(w, u64::from(self.count))
            .map_err(|e| e.at("triggers"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.triggers;
        crate::json::key(w, &mut first, "triggers")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EventTriggerStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["count", "triggers"])?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_triggers = o.req("triggers", <crate::bounded::BoundedVec<crate::types::TriggerStatusEntry, 126> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            count: p_count,
            triggers: p_triggers,
        })
    }
}

impl EventTriggerStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for EventTriggerStatus {
    const DESCRIPTOR: u8 = 0xB6;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "event_trigger_status";
}

/// Get event action status. Report the type and trigger of event actions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetEventActionStatus {
    /// Number of entries requested; 0 requests all action slots.
    pub requested_count: u8,
    /// Action instances to query.
    pub requested_instances: crate::bounded::BoundedVec<u8, 252>,
}

impl Default for GetEventActionStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetEventActionStatus {
    const ZERO: Self = Self {
        requested_count: <u8 as crate::wire::Wire>::ZERO,
        requested_instances: <crate::bounded::BoundedVec<u8, 252> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_requested_count =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("requested_count"))?;
        let p_requested_instances =
            crate::bounded::BoundedVec::<u8, 252>::decode_counted(r, u64::from(p_requested_count))
                .map_err(|e| e.at("requested_instances"))?;
        Ok(Self {
            requested_count: p_requested_count,
            requested_instances: p_requested_instances,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.requested_count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("requested_count"))?;
        let v = &self.requested_instances;
        v.encode_counted(w, u64::from(self.requested_count))
            .map_err(|e| e.at("requested_instances"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.requested_count;
        crate::json::key(w, &mut first, "requested_count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.requested_instances;
        crate::json::key(w, &mut first, "requested_instances")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GetEventActionStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["requested_count", "requested_instances"])?;
        let p_requested_count = o.req(
            "requested_count",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_requested_instances = o.req(
            "requested_instances",
            <crate::bounded::BoundedVec<u8, 252> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            requested_count: p_requested_count,
            requested_instances: p_requested_instances,
        })
    }
}

impl GetEventActionStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GetEventActionStatus {
    const DESCRIPTOR: u8 = 0x2D;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "get_event_action_status";
}

/// Event action status. Status of the requested actions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventActionStatus {
    /// Number of entries.
    pub count: u8,
    /// The configured actions.
    pub actions: crate::bounded::BoundedVec<crate::types::ActionStatusEntry, 126>,
}

impl Default for EventActionStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EventActionStatus {
    const ZERO: Self = Self {
        count: <u8 as crate::wire::Wire>::ZERO,
        actions: <crate::bounded::BoundedVec<crate::types::ActionStatusEntry, 126> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        let p_actions =
            crate::bounded::BoundedVec::<crate::types::ActionStatusEntry, 126>::decode_counted(
                r,
                u64::from(p_count),
            )
            .map_err(|e| e.at("actions"))?;
        Ok(Self {
            count: p_count,
            actions: p_actions,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        let v = &self.actions;
        v.encode_counted(w, u64::from(self.count))
            .map_err(|e| e.at("actions"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.actions;
        crate::json::key(w, &mut first, "actions")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EventActionStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["count", "actions"])?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_actions = o.req("actions", <crate::bounded::BoundedVec<crate::types::ActionStatusEntry, 126> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            count: p_count,
            actions: p_actions,
        })
    }
}

impl EventActionStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for EventActionStatus {
    const DESCRIPTOR: u8 = 0xB7;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "event_action_status";
}

/// Event trigger configuration. Configure an event trigger (GPIO, threshold or combination).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventTriggerConfig {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Trigger number; 0 applies to all instances for save, load and default. Sent for: write, read, save, load, default.
    pub instance: u8,
    /// Type of trigger. Sent for: write.
    pub r#type: Option<crate::types::TriggerType>,
    /// Parameters of the trigger type. Sent for: write.
    pub parameters: Option<crate::types::TriggerParams>,
}

impl Default for EventTriggerConfig {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EventTriggerConfig {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        instance: <u8 as crate::wire::Wire>::ZERO,
        r#type: None,
        parameters: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_instance = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("instance"))?;
        let p_type = if r.left() > 0 {
            Some(
                <crate::types::TriggerType as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("type"))?,
            )
        } else {
            None
        };
        let p_parameters = if r.left() > 0 {
            Some(
                crate::types::TriggerParams::decode_selected(r, p_type.map_or(0, |s| s.0))
                    .map_err(|e| e.at("parameters"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            instance: p_instance,
            r#type: p_type,
            parameters: p_parameters,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.instance;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("instance"))?;
        if let Some(v) = &self.r#type {
            optionals.present("type")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        } else {
            optionals.absent("type");
        }
        if let Some(v) = &self.parameters {
            optionals.present("parameters")?;
            v.encode_selected(w, self.r#type.map_or(0, |s| s.0))
                .map_err(|e| e.at("parameters"))?;
        } else {
            optionals.absent("parameters");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.instance;
        crate::json::key(w, &mut first, "instance")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.r#type {
            crate::json::key(w, &mut first, "type")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.parameters {
            crate::json::key(w, &mut first, "parameters")?;
            v.write_json(w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EventTriggerConfig {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "instance", "type", "parameters"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_instance = o.req("instance", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_type = o.opt(
            "type",
            <crate::types::TriggerType as crate::json_read::FromJson>::from_json,
        )?;
        let p_parameters = o.opt("parameters", |v| {
            crate::types::TriggerParams::from_json_selected(v, p_type.map_or(0, |s| s.0))
        })?;
        Ok(Self {
            function: p_function,
            instance: p_instance,
            r#type: p_type,
            parameters: p_parameters,
        })
    }
}

impl EventTriggerConfig {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for EventTriggerConfig {
    const DESCRIPTOR: u8 = 0x2E;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "event_trigger_config";
}

/// Event trigger configuration (response). Current configuration of a trigger.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventTriggerConfigResponse {
    /// Trigger number.
    pub instance: u8,
    /// Type of trigger.
    pub r#type: crate::types::TriggerType,
    /// Parameters of the trigger type.
    pub parameters: crate::types::TriggerParams,
}

impl Default for EventTriggerConfigResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EventTriggerConfigResponse {
    const ZERO: Self = Self {
        instance: <u8 as crate::wire::Wire>::ZERO,
        r#type: <crate::types::TriggerType as crate::wire::Wire>::ZERO,
        parameters: crate::types::TriggerParams::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_instance = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("instance"))?;
        let p_type = <crate::types::TriggerType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("type"))?;
        let p_parameters = crate::types::TriggerParams::decode_selected(r, p_type.0)
            .map_err(|e| e.at("parameters"))?;
        Ok(Self {
            instance: p_instance,
            r#type: p_type,
            parameters: p_parameters,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.instance;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("instance"))?;
        let v = &self.r#type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        let v = &self.parameters;
        v.encode_selected(w, self.r#type.0)
            .map_err(|e| e.at("parameters"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.instance;
        crate::json::key(w, &mut first, "instance")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.r#type;
        crate::json::key(w, &mut first, "type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.parameters;
        crate::json::key(w, &mut first, "parameters")?;
        v.write_json(w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EventTriggerConfigResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["instance", "type", "parameters"])?;
        let p_instance = o.req("instance", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_type = o.req(
            "type",
            <crate::types::TriggerType as crate::json_read::FromJson>::from_json,
        )?;
        let p_parameters = o.req("parameters", |v| {
            crate::types::TriggerParams::from_json_selected(v, p_type.0)
        })?;
        Ok(Self {
            instance: p_instance,
            r#type: p_type,
            parameters: p_parameters,
        })
    }
}

impl EventTriggerConfigResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for EventTriggerConfigResponse {
    const DESCRIPTOR: u8 = 0xB8;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "event_trigger_config_response";
}

/// Event action configuration. Configure an event action (GPIO or message) and the trigger that fires it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventActionConfig {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Action number; 0 applies to all instances for save, load and default. Sent for: write, read, save, load, default.
    pub instance: u8,
    /// Trigger ID number. Sent for: write.
    pub trigger: Option<u8>,
    /// Type of action. Sent for: write.
    pub r#type: Option<crate::types::ActionType>,
    /// Parameters of the action type. Sent for: write.
    pub parameters: Option<crate::types::ActionParams>,
}

impl Default for EventActionConfig {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EventActionConfig {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        instance: <u8 as crate::wire::Wire>::ZERO,
        trigger: None,
        r#type: None,
        parameters: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_instance = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("instance"))?;
        let p_trigger = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("trigger"))?)
        } else {
            None
        };
        let p_type = if r.left() > 0 {
            Some(
                <crate::types::ActionType as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("type"))?,
            )
        } else {
            None
        };
        let p_parameters = if r.left() > 0 {
            Some(
                crate::types::ActionParams::decode_selected(r, p_type.map_or(0, |s| s.0))
                    .map_err(|e| e.at("parameters"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            instance: p_instance,
            trigger: p_trigger,
            r#type: p_type,
            parameters: p_parameters,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.instance;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("instance"))?;
        if let Some(v) = &self.trigger {
            optionals.present("trigger")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("trigger"))?;
        } else {
            optionals.absent("trigger");
        }
        if let Some(v) = &self.r#type {
            optionals.present("type")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        } else {
            optionals.absent("type");
        }
        if let Some(v) = &self.parameters {
            optionals.present("parameters")?;
            v.encode_selected(w, self.r#type.map_or(0, |s| s.0))
                .map_err(|e| e.at("parameters"))?;
        } else {
            optionals.absent("parameters");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.instance;
        crate::json::key(w, &mut first, "instance")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.trigger {
            crate::json::key(w, &mut first, "trigger")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.r#type {
            crate::json::key(w, &mut first, "type")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.parameters {
            crate::json::key(w, &mut first, "parameters")?;
            v.write_json(w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EventActionConfig {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["function", "instance", "trigger", "type", "parameters"],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_instance = o.req("instance", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_trigger = o.opt("trigger", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_type = o.opt(
            "type",
            <crate::types::ActionType as crate::json_read::FromJson>::from_json,
        )?;
        let p_parameters = o.opt("parameters", |v| {
            crate::types::ActionParams::from_json_selected(v, p_type.map_or(0, |s| s.0))
        })?;
        Ok(Self {
            function: p_function,
            instance: p_instance,
            trigger: p_trigger,
            r#type: p_type,
            parameters: p_parameters,
        })
    }
}

impl EventActionConfig {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for EventActionConfig {
    const DESCRIPTOR: u8 = 0x2F;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "event_action_config";
}

/// Event action configuration (response). Current configuration of an action.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventActionConfigResponse {
    /// Action number.
    pub instance: u8,
    /// Trigger ID number.
    pub trigger: u8,
    /// Type of action.
    pub r#type: crate::types::ActionType,
    /// Parameters of the action type.
    pub parameters: crate::types::ActionParams,
}

impl Default for EventActionConfigResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for EventActionConfigResponse {
    const ZERO: Self = Self {
        instance: <u8 as crate::wire::Wire>::ZERO,
        trigger: <u8 as crate::wire::Wire>::ZERO,
        r#type: <crate::types::ActionType as crate::wire::Wire>::ZERO,
        parameters: crate::types::ActionParams::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_instance = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("instance"))?;
        let p_trigger = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("trigger"))?;
        let p_type =
            <crate::types::ActionType as crate::wire::Wire>::decode(r).map_err(|e| e.at("type"))?;
        let p_parameters = crate::types::ActionParams::decode_selected(r, p_type.0)
            .map_err(|e| e.at("parameters"))?;
        Ok(Self {
            instance: p_instance,
            trigger: p_trigger,
            r#type: p_type,
            parameters: p_parameters,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.instance;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("instance"))?;
        let v = &self.trigger;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("trigger"))?;
        let v = &self.r#type;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("type"))?;
        let v = &self.parameters;
        v.encode_selected(w, self.r#type.0)
            .map_err(|e| e.at("parameters"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.instance;
        crate::json::key(w, &mut first, "instance")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.trigger;
        crate::json::key(w, &mut first, "trigger")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.r#type;
        crate::json::key(w, &mut first, "type")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.parameters;
        crate::json::key(w, &mut first, "parameters")?;
        v.write_json(w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for EventActionConfigResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["instance", "trigger", "type", "parameters"])?;
        let p_instance = o.req("instance", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_trigger = o.req("trigger", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_type = o.req(
            "type",
            <crate::types::ActionType as crate::json_read::FromJson>::from_json,
        )?;
        let p_parameters = o.req("parameters", |v| {
            crate::types::ActionParams::from_json_selected(v, p_type.0)
        })?;
        Ok(Self {
            instance: p_instance,
            trigger: p_trigger,
            r#type: p_type,
            parameters: p_parameters,
        })
    }
}

impl EventActionConfigResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for EventActionConfigResponse {
    const DESCRIPTOR: u8 = 0xB9;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "event_action_config_response";
}

/// Device startup settings. Layout for device gx5_45.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceStartupSettingsGx5_45 {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
}

impl Default for DeviceStartupSettingsGx5_45 {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceStartupSettingsGx5_45 {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        Ok(Self {
            function: p_function,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeviceStartupSettingsGx5_45 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
        })
    }
}

impl DeviceStartupSettingsGx5_45 {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for DeviceStartupSettingsGx5_45 {
    const DESCRIPTOR: u8 = 0x30;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "device_startup_settings";
}

/// Device startup settings. Layout for device cv7_ins.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceStartupSettingsCv7Ins {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
}

impl Default for DeviceStartupSettingsCv7Ins {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceStartupSettingsCv7Ins {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        Ok(Self {
            function: p_function,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeviceStartupSettingsCv7Ins {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
        })
    }
}

impl DeviceStartupSettingsCv7Ins {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for DeviceStartupSettingsCv7Ins {
    const DESCRIPTOR: u8 = 0x30;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "device_startup_settings";
}

/// Device startup settings. Save all current settings as the startup settings, load the saved startup settings, or reset all settings to the factory defaults. Saving may briefly disturb data output and can take up to a second.
///
/// The layout differs per device; one variant per device, in spec order.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DeviceStartupSettings {
    /// Layout for device `gx5_45`.
    Gx5_45(DeviceStartupSettingsGx5_45),
    /// Layout for device `cv7_ins`.
    Cv7Ins(DeviceStartupSettingsCv7Ins),
}

impl DeviceStartupSettings {
    /// Field descriptor.
    pub const DESCRIPTOR: u8 = 0x30;
    /// Field name as printed in JSON.
    pub const NAME: &'static str = "device_startup_settings";

    /// Device whose layout this value uses.
    pub fn device(&self) -> crate::Device {
        match self {
            Self::Gx5_45(_) => crate::Device::Gx5_45,
            Self::Cv7Ins(_) => crate::Device::Cv7Ins,
        }
    }

    /// Decodes with `device`'s layout if it has one, else tries the layouts in spec order and
    /// keeps the first that decodes (reporting the first layout's error if none does).
    pub fn decode_data(
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Result<Self, crate::error::DecodeError> {
        if device == Some(crate::Device::Gx5_45) {
            return <DeviceStartupSettingsGx5_45 as crate::wire::Layout>::decode_data(data)
                .map(Self::Gx5_45);
        }
        if device == Some(crate::Device::Cv7Ins) {
            return <DeviceStartupSettingsCv7Ins as crate::wire::Layout>::decode_data(data)
                .map(Self::Cv7Ins);
        }
        let first = match <DeviceStartupSettingsGx5_45 as crate::wire::Layout>::decode_data(data) {
            Ok(v) => return Ok(Self::Gx5_45(v)),
            Err(e) => e,
        };
        if let Ok(v) = <DeviceStartupSettingsCv7Ins as crate::wire::Layout>::decode_data(data) {
            return Ok(Self::Cv7Ins(v));
        }
        Err(first)
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Gx5_45(v) => crate::wire::Layout::encode_data(v, w),
            Self::Cv7Ins(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Gx5_45(v) => crate::wire::Wire::write_json(v, w),
            Self::Cv7Ins(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the values of `device`'s layout.
    #[cfg(feature = "std")]
    pub fn from_json(
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        match device {
            Some(crate::Device::Gx5_45) => <DeviceStartupSettingsGx5_45 as crate::json_read::FromJson>::from_json(values)
                .map(Self::Gx5_45)
                .map_err(|e| e.at("values")),
            Some(crate::Device::Cv7Ins) => <DeviceStartupSettingsCv7Ins as crate::json_read::FromJson>::from_json(values)
                .map(Self::Cv7Ins)
                .map_err(|e| e.at("values")),
            None => Err(crate::json_read::JsonError::new(
                "field device_startup_settings has per-device layouts; name one with \"device\" (gx5_45, cv7_ins)",
            )
            .at("device")),
        }
    }
}

/// Sensor-to-vehicle frame transformation (Euler). Mounting angles of the sensor in the vehicle frame as roll, pitch and yaw: the transformation of vectors from the sensor frame to the vehicle frame (the inverse of the rotation used by older products). Applied to the IMU and estimation filter outputs; changing it resets the low-pass, complementary and estimation filters. Read-back angles may differ but are equivalent.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorToVehicleEuler {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Roll angle. Units: rad. Sent for: write.
    pub roll: Option<f32>,
    /// Pitch angle. Units: rad. Sent for: write.
    pub pitch: Option<f32>,
    /// Yaw angle. Units: rad. Sent for: write.
    pub yaw: Option<f32>,
}

impl Default for SensorToVehicleEuler {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorToVehicleEuler {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        roll: None,
        pitch: None,
        yaw: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_roll = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("roll"))?)
        } else {
            None
        };
        let p_pitch = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pitch"))?)
        } else {
            None
        };
        let p_yaw = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("yaw"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            roll: p_roll,
            pitch: p_pitch,
            yaw: p_yaw,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.roll {
            optionals.present("roll")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("roll"))?;
        } else {
            optionals.absent("roll");
        }
        if let Some(v) = &self.pitch {
            optionals.present("pitch")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("pitch"))?;
        } else {
            optionals.absent("pitch");
        }
        if let Some(v) = &self.yaw {
            optionals.present("yaw")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("yaw"))?;
        } else {
            optionals.absent("yaw");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.roll {
            crate::json::key(w, &mut first, "roll")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.pitch {
            crate::json::key(w, &mut first, "pitch")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.yaw {
            crate::json::key(w, &mut first, "yaw")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorToVehicleEuler {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "roll", "pitch", "yaw"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_roll = o.opt("roll", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_pitch = o.opt("pitch", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_yaw = o.opt("yaw", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            roll: p_roll,
            pitch: p_pitch,
            yaw: p_yaw,
        })
    }
}

impl SensorToVehicleEuler {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for SensorToVehicleEuler {
    const DESCRIPTOR: u8 = 0x31;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "sensor_to_vehicle_euler";
}

/// Sensor-to-vehicle frame transformation (Euler) (response). Current sensor-to-vehicle transformation as Euler angles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorToVehicleEulerResponse {
    /// Roll angle. Units: rad.
    pub roll: f32,
    /// Pitch angle. Units: rad.
    pub pitch: f32,
    /// Yaw angle. Units: rad.
    pub yaw: f32,
}

impl Default for SensorToVehicleEulerResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorToVehicleEulerResponse {
    const ZERO: Self = Self {
        roll: <f32 as crate::wire::Wire>::ZERO,
        pitch: <f32 as crate::wire::Wire>::ZERO,
        yaw: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_roll = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("roll"))?;
        let p_pitch = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pitch"))?;
        let p_yaw = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("yaw"))?;
        Ok(Self {
            roll: p_roll,
            pitch: p_pitch,
            yaw: p_yaw,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.roll;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("roll"))?;
        let v = &self.pitch;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pitch"))?;
        let v = &self.yaw;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("yaw"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.roll;
        crate::json::key(w, &mut first, "roll")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pitch;
        crate::json::key(w, &mut first, "pitch")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.yaw;
        crate::json::key(w, &mut first, "yaw")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorToVehicleEulerResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["roll", "pitch", "yaw"])?;
        let p_roll = o.req("roll", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_pitch = o.req("pitch", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_yaw = o.req("yaw", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            roll: p_roll,
            pitch: p_pitch,
            yaw: p_yaw,
        })
    }
}

impl SensorToVehicleEulerResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for SensorToVehicleEulerResponse {
    const DESCRIPTOR: u8 = 0xB1;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "sensor_to_vehicle_euler_response";
}

/// Sensor-to-vehicle frame transformation (quaternion). Sensor-to-vehicle transformation as a unit quaternion \[w, i, j, k\]. Same effects as the Euler form; a quaternion read back may differ but is equivalent.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorToVehicleQuaternion {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Unit quaternion of the transformation, \[w, i, j, k\]. Sent for: write.
    pub q: Option<[f32; 4]>,
}

impl Default for SensorToVehicleQuaternion {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorToVehicleQuaternion {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        q: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_q = if r.left() > 0 {
            Some(<[f32; 4] as crate::wire::Wire>::decode(r).map_err(|e| e.at("q"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            q: p_q,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.q {
            optionals.present("q")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("q"))?;
        } else {
            optionals.absent("q");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.q {
            crate::json::key(w, &mut first, "q")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorToVehicleQuaternion {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "q"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_q = o.opt("q", <[f32; 4] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            q: p_q,
        })
    }
}

impl SensorToVehicleQuaternion {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for SensorToVehicleQuaternion {
    const DESCRIPTOR: u8 = 0x32;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "sensor_to_vehicle_quaternion";
}

/// Sensor-to-vehicle frame transformation (quaternion) (response). Current sensor-to-vehicle transformation as a unit quaternion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorToVehicleQuaternionResponse {
    /// Unit quaternion of the transformation, \[w, i, j, k\].
    pub q: [f32; 4],
}

impl Default for SensorToVehicleQuaternionResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorToVehicleQuaternionResponse {
    const ZERO: Self = Self {
        q: <[f32; 4] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(16);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_q = <[f32; 4] as crate::wire::Wire>::decode(r).map_err(|e| e.at("q"))?;
        Ok(Self { q: p_q })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.q;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("q"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.q;
        crate::json::key(w, &mut first, "q")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorToVehicleQuaternionResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["q"])?;
        let p_q = o.req("q", <[f32; 4] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { q: p_q })
    }
}

impl SensorToVehicleQuaternionResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for SensorToVehicleQuaternionResponse {
    const DESCRIPTOR: u8 = 0xB2;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "sensor_to_vehicle_quaternion_response";
}

/// Sensor-to-vehicle frame transformation (direction cosine matrix). Sensor-to-vehicle transformation as a 3x3 direction cosine matrix in row-major order (v_vehicle = M v_sensor). Same effects as the Euler form.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorToVehicleDcm {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Direction cosine matrix, row-major. Sent for: write.
    pub dcm: Option<[f32; 9]>,
}

impl Default for SensorToVehicleDcm {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorToVehicleDcm {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        dcm: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_dcm = if r.left() > 0 {
            Some(<[f32; 9] as crate::wire::Wire>::decode(r).map_err(|e| e.at("dcm"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            dcm: p_dcm,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.dcm {
            optionals.present("dcm")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("dcm"))?;
        } else {
            optionals.absent("dcm");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.dcm {
            crate::json::key(w, &mut first, "dcm")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorToVehicleDcm {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "dcm"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_dcm = o.opt("dcm", <[f32; 9] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            dcm: p_dcm,
        })
    }
}

impl SensorToVehicleDcm {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for SensorToVehicleDcm {
    const DESCRIPTOR: u8 = 0x33;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "sensor_to_vehicle_dcm";
}

/// Sensor-to-vehicle frame transformation (DCM) (response). Current sensor-to-vehicle transformation as a row-major direction cosine matrix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorToVehicleDcmResponse {
    /// Direction cosine matrix, row-major.
    pub dcm: [f32; 9],
}

impl Default for SensorToVehicleDcmResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorToVehicleDcmResponse {
    const ZERO: Self = Self {
        dcm: <[f32; 9] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(36);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_dcm = <[f32; 9] as crate::wire::Wire>::decode(r).map_err(|e| e.at("dcm"))?;
        Ok(Self { dcm: p_dcm })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.dcm;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("dcm"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.dcm;
        crate::json::key(w, &mut first, "dcm")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorToVehicleDcmResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["dcm"])?;
        let p_dcm = o.req("dcm", <[f32; 9] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { dcm: p_dcm })
    }
}

impl SensorToVehicleDcmResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for SensorToVehicleDcmResponse {
    const DESCRIPTOR: u8 = 0xB3;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "sensor_to_vehicle_dcm_response";
}

/// Accelerometer bias. Layout for device gx5_45.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelBiasGx5_45 {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// X, Y, Z accelerometer bias. Units: g. Sent for: write, write_no_ack.
    pub bias: Option<[f32; 3]>,
}

impl Default for AccelBiasGx5_45 {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelBiasGx5_45 {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        bias: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_bias = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            bias: p_bias,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.bias {
            optionals.present("bias")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias"))?;
        } else {
            optionals.absent("bias");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.bias {
            crate::json::key(w, &mut first, "bias")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelBiasGx5_45 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "bias"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_bias = o.opt("bias", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            bias: p_bias,
        })
    }
}

impl AccelBiasGx5_45 {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for AccelBiasGx5_45 {
    const DESCRIPTOR: u8 = 0x37;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "accel_bias";
}

/// Accelerometer bias. Layout for device cv7_ins.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelBiasCv7Ins {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// X, Y, Z accelerometer bias in the sensor frame. Units: g. Sent for: write.
    pub bias: Option<[f32; 3]>,
}

impl Default for AccelBiasCv7Ins {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelBiasCv7Ins {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        bias: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_bias = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            bias: p_bias,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.bias {
            optionals.present("bias")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias"))?;
        } else {
            optionals.absent("bias");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.bias {
            crate::json::key(w, &mut first, "bias")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelBiasCv7Ins {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "bias"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_bias = o.opt("bias", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            bias: p_bias,
        })
    }
}

impl AccelBiasCv7Ins {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for AccelBiasCv7Ins {
    const DESCRIPTOR: u8 = 0x37;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "accel_bias";
}

/// Accelerometer bias. User accelerometer bias in the sensor frame, subtracted from the scaled (calibrated) accelerometer output.
///
/// The layout differs per device; one variant per device, in spec order.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AccelBias {
    /// Layout for device `gx5_45`.
    Gx5_45(AccelBiasGx5_45),
    /// Layout for device `cv7_ins`.
    Cv7Ins(AccelBiasCv7Ins),
}

impl AccelBias {
    /// Field descriptor.
    pub const DESCRIPTOR: u8 = 0x37;
    /// Field name as printed in JSON.
    pub const NAME: &'static str = "accel_bias";

    /// Device whose layout this value uses.
    pub fn device(&self) -> crate::Device {
        match self {
            Self::Gx5_45(_) => crate::Device::Gx5_45,
            Self::Cv7Ins(_) => crate::Device::Cv7Ins,
        }
    }

    /// Decodes with `device`'s layout if it has one, else tries the layouts in spec order and
    /// keeps the first that decodes (reporting the first layout's error if none does).
    pub fn decode_data(
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Result<Self, crate::error::DecodeError> {
        if device == Some(crate::Device::Gx5_45) {
            return <AccelBiasGx5_45 as crate::wire::Layout>::decode_data(data).map(Self::Gx5_45);
        }
        if device == Some(crate::Device::Cv7Ins) {
            return <AccelBiasCv7Ins as crate::wire::Layout>::decode_data(data).map(Self::Cv7Ins);
        }
        let first = match <AccelBiasGx5_45 as crate::wire::Layout>::decode_data(data) {
            Ok(v) => return Ok(Self::Gx5_45(v)),
            Err(e) => e,
        };
        if let Ok(v) = <AccelBiasCv7Ins as crate::wire::Layout>::decode_data(data) {
            return Ok(Self::Cv7Ins(v));
        }
        Err(first)
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Gx5_45(v) => crate::wire::Layout::encode_data(v, w),
            Self::Cv7Ins(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Gx5_45(v) => crate::wire::Wire::write_json(v, w),
            Self::Cv7Ins(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the values of `device`'s layout.
    #[cfg(feature = "std")]
    pub fn from_json(
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        match device {
            Some(crate::Device::Gx5_45) => <AccelBiasGx5_45 as crate::json_read::FromJson>::from_json(values)
                .map(Self::Gx5_45)
                .map_err(|e| e.at("values")),
            Some(crate::Device::Cv7Ins) => <AccelBiasCv7Ins as crate::json_read::FromJson>::from_json(values)
                .map(Self::Cv7Ins)
                .map_err(|e| e.at("values")),
            None => Err(crate::json_read::JsonError::new(
                "field accel_bias has per-device layouts; name one with \"device\" (gx5_45, cv7_ins)",
            )
            .at("device")),
        }
    }
}

/// Accelerometer bias (response). Current user accelerometer bias.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelBiasResponse {
    /// X, Y, Z accelerometer bias in the sensor frame. Units: g.
    pub bias: [f32; 3],
}

impl Default for AccelBiasResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AccelBiasResponse {
    const ZERO: Self = Self {
        bias: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_bias = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias"))?;
        Ok(Self { bias: p_bias })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.bias;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.bias;
        crate::json::key(w, &mut first, "bias")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AccelBiasResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["bias"])?;
        let p_bias = o.req("bias", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { bias: p_bias })
    }
}

impl AccelBiasResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for AccelBiasResponse {
    const DESCRIPTOR: u8 = 0x9A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "accel_bias_response";
}

/// Gyro bias. Layout for device gx5_45.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroBiasGx5_45 {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// X, Y, Z gyro bias. Units: rad/s. Sent for: write, write_no_ack.
    pub bias: Option<[f32; 3]>,
}

impl Default for GyroBiasGx5_45 {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroBiasGx5_45 {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        bias: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_bias = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            bias: p_bias,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.bias {
            optionals.present("bias")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias"))?;
        } else {
            optionals.absent("bias");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.bias {
            crate::json::key(w, &mut first, "bias")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroBiasGx5_45 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "bias"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_bias = o.opt("bias", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            bias: p_bias,
        })
    }
}

impl GyroBiasGx5_45 {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GyroBiasGx5_45 {
    const DESCRIPTOR: u8 = 0x38;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gyro_bias";
}

/// Gyro bias. Layout for device cv7_ins.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroBiasCv7Ins {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// X, Y, Z gyro bias in the sensor frame. Units: rad/s. Sent for: write.
    pub bias: Option<[f32; 3]>,
}

impl Default for GyroBiasCv7Ins {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroBiasCv7Ins {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        bias: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_bias = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            bias: p_bias,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.bias {
            optionals.present("bias")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias"))?;
        } else {
            optionals.absent("bias");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.bias {
            crate::json::key(w, &mut first, "bias")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroBiasCv7Ins {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "bias"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_bias = o.opt("bias", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            bias: p_bias,
        })
    }
}

impl GyroBiasCv7Ins {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GyroBiasCv7Ins {
    const DESCRIPTOR: u8 = 0x38;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gyro_bias";
}

/// Gyro bias. User gyro bias in the sensor frame, subtracted from the scaled (calibrated) angular rate output.
///
/// The layout differs per device; one variant per device, in spec order.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GyroBias {
    /// Layout for device `gx5_45`.
    Gx5_45(GyroBiasGx5_45),
    /// Layout for device `cv7_ins`.
    Cv7Ins(GyroBiasCv7Ins),
}

impl GyroBias {
    /// Field descriptor.
    pub const DESCRIPTOR: u8 = 0x38;
    /// Field name as printed in JSON.
    pub const NAME: &'static str = "gyro_bias";

    /// Device whose layout this value uses.
    pub fn device(&self) -> crate::Device {
        match self {
            Self::Gx5_45(_) => crate::Device::Gx5_45,
            Self::Cv7Ins(_) => crate::Device::Cv7Ins,
        }
    }

    /// Decodes with `device`'s layout if it has one, else tries the layouts in spec order and
    /// keeps the first that decodes (reporting the first layout's error if none does).
    pub fn decode_data(
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Result<Self, crate::error::DecodeError> {
        if device == Some(crate::Device::Gx5_45) {
            return <GyroBiasGx5_45 as crate::wire::Layout>::decode_data(data).map(Self::Gx5_45);
        }
        if device == Some(crate::Device::Cv7Ins) {
            return <GyroBiasCv7Ins as crate::wire::Layout>::decode_data(data).map(Self::Cv7Ins);
        }
        let first = match <GyroBiasGx5_45 as crate::wire::Layout>::decode_data(data) {
            Ok(v) => return Ok(Self::Gx5_45(v)),
            Err(e) => e,
        };
        if let Ok(v) = <GyroBiasCv7Ins as crate::wire::Layout>::decode_data(data) {
            return Ok(Self::Cv7Ins(v));
        }
        Err(first)
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Gx5_45(v) => crate::wire::Layout::encode_data(v, w),
            Self::Cv7Ins(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Gx5_45(v) => crate::wire::Wire::write_json(v, w),
            Self::Cv7Ins(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the values of `device`'s layout.
    #[cfg(feature = "std")]
    pub fn from_json(
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        match device {
            Some(crate::Device::Gx5_45) => <GyroBiasGx5_45 as crate::json_read::FromJson>::from_json(values)
                .map(Self::Gx5_45)
                .map_err(|e| e.at("values")),
            Some(crate::Device::Cv7Ins) => <GyroBiasCv7Ins as crate::json_read::FromJson>::from_json(values)
                .map(Self::Cv7Ins)
                .map_err(|e| e.at("values")),
            None => Err(crate::json_read::JsonError::new(
                "field gyro_bias has per-device layouts; name one with \"device\" (gx5_45, cv7_ins)",
            )
            .at("device")),
        }
    }
}

/// Gyro bias (response). Current user gyro bias; also the reply to Capture Gyro Bias (0x39), carrying the newly captured bias.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroBiasResponse {
    /// X, Y, Z gyro bias in the sensor frame. Units: rad/s.
    pub bias: [f32; 3],
}

impl Default for GyroBiasResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GyroBiasResponse {
    const ZERO: Self = Self {
        bias: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_bias = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("bias"))?;
        Ok(Self { bias: p_bias })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.bias;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("bias"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.bias;
        crate::json::key(w, &mut first, "bias")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GyroBiasResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["bias"])?;
        let p_bias = o.req("bias", <[f32; 3] as crate::json_read::FromJson>::from_json)?;
        Ok(Self { bias: p_bias })
    }
}

impl GyroBiasResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GyroBiasResponse {
    const DESCRIPTOR: u8 = 0x9B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gyro_bias_response";
}

/// Capture gyro bias. Average the gyro output for the given time and write the result to the gyro bias (in RAM only; save it with Gyro Bias 0x38). The device must be stationary, with minimal vibration. The reply carries the captured bias (0x9B).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CaptureGyroBias {
    /// Sampling time, 1000 to 30000 ms. Units: ms.
    pub averaging_time_ms: u16,
}

impl Default for CaptureGyroBias {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CaptureGyroBias {
    const ZERO: Self = Self {
        averaging_time_ms: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_averaging_time_ms =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("averaging_time_ms"))?;
        Ok(Self {
            averaging_time_ms: p_averaging_time_ms,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.averaging_time_ms;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("averaging_time_ms"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.averaging_time_ms;
        crate::json::key(w, &mut first, "averaging_time_ms")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CaptureGyroBias {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["averaging_time_ms"])?;
        let p_averaging_time_ms = o.req(
            "averaging_time_ms",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            averaging_time_ms: p_averaging_time_ms,
        })
    }
}

impl CaptureGyroBias {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for CaptureGyroBias {
    const DESCRIPTOR: u8 = 0x39;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "capture_gyro_bias";
}

/// Magnetometer hard iron offset. Layout for device gx5_45.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagHardIronOffsetGx5_45 {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// X, Y, Z hard iron offset. Units: gauss. Sent for: write, write_no_ack.
    pub offset: Option<[f32; 3]>,
}

impl Default for MagHardIronOffsetGx5_45 {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagHardIronOffsetGx5_45 {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        offset: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_offset = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("offset"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            offset: p_offset,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.offset {
            optionals.present("offset")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("offset"))?;
        } else {
            optionals.absent("offset");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.offset {
            crate::json::key(w, &mut first, "offset")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagHardIronOffsetGx5_45 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "offset"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_offset = o.opt(
            "offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            offset: p_offset,
        })
    }
}

impl MagHardIronOffsetGx5_45 {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for MagHardIronOffsetGx5_45 {
    const DESCRIPTOR: u8 = 0x3A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "mag_hard_iron_offset";
}

/// Magnetometer hard iron offset. Layout for device cv7_ins.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagHardIronOffsetCv7Ins {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// X, Y, Z hard iron offset in the sensor frame. Units: gauss. Sent for: write.
    pub offset: Option<[f32; 3]>,
}

impl Default for MagHardIronOffsetCv7Ins {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagHardIronOffsetCv7Ins {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        offset: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_offset = if r.left() > 0 {
            Some(<[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("offset"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            offset: p_offset,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.offset {
            optionals.present("offset")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("offset"))?;
        } else {
            optionals.absent("offset");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.offset {
            crate::json::key(w, &mut first, "offset")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagHardIronOffsetCv7Ins {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "offset"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_offset = o.opt(
            "offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            offset: p_offset,
        })
    }
}

impl MagHardIronOffsetCv7Ins {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for MagHardIronOffsetCv7Ins {
    const DESCRIPTOR: u8 = 0x3A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "mag_hard_iron_offset";
}

/// Magnetometer hard iron offset. User magnetometer hard iron offset in the sensor frame, subtracted from the scaled magnetometer output. Determined from calibration data after installation (MicroStrain tools or in-run auto-calibration where supported). Default \[0, 0, 0\].
///
/// The layout differs per device; one variant per device, in spec order.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MagHardIronOffset {
    /// Layout for device `gx5_45`.
    Gx5_45(MagHardIronOffsetGx5_45),
    /// Layout for device `cv7_ins`.
    Cv7Ins(MagHardIronOffsetCv7Ins),
}

impl MagHardIronOffset {
    /// Field descriptor.
    pub const DESCRIPTOR: u8 = 0x3A;
    /// Field name as printed in JSON.
    pub const NAME: &'static str = "mag_hard_iron_offset";

    /// Device whose layout this value uses.
    pub fn device(&self) -> crate::Device {
        match self {
            Self::Gx5_45(_) => crate::Device::Gx5_45,
            Self::Cv7Ins(_) => crate::Device::Cv7Ins,
        }
    }

    /// Decodes with `device`'s layout if it has one, else tries the layouts in spec order and
    /// keeps the first that decodes (reporting the first layout's error if none does).
    pub fn decode_data(
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Result<Self, crate::error::DecodeError> {
        if device == Some(crate::Device::Gx5_45) {
            return <MagHardIronOffsetGx5_45 as crate::wire::Layout>::decode_data(data)
                .map(Self::Gx5_45);
        }
        if device == Some(crate::Device::Cv7Ins) {
            return <MagHardIronOffsetCv7Ins as crate::wire::Layout>::decode_data(data)
                .map(Self::Cv7Ins);
        }
        let first = match <MagHardIronOffsetGx5_45 as crate::wire::Layout>::decode_data(data) {
            Ok(v) => return Ok(Self::Gx5_45(v)),
            Err(e) => e,
        };
        if let Ok(v) = <MagHardIronOffsetCv7Ins as crate::wire::Layout>::decode_data(data) {
            return Ok(Self::Cv7Ins(v));
        }
        Err(first)
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Gx5_45(v) => crate::wire::Layout::encode_data(v, w),
            Self::Cv7Ins(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Gx5_45(v) => crate::wire::Wire::write_json(v, w),
            Self::Cv7Ins(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the values of `device`'s layout.
    #[cfg(feature = "std")]
    pub fn from_json(
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        match device {
            Some(crate::Device::Gx5_45) => <MagHardIronOffsetGx5_45 as crate::json_read::FromJson>::from_json(values)
                .map(Self::Gx5_45)
                .map_err(|e| e.at("values")),
            Some(crate::Device::Cv7Ins) => <MagHardIronOffsetCv7Ins as crate::json_read::FromJson>::from_json(values)
                .map(Self::Cv7Ins)
                .map_err(|e| e.at("values")),
            None => Err(crate::json_read::JsonError::new(
                "field mag_hard_iron_offset has per-device layouts; name one with \"device\" (gx5_45, cv7_ins)",
            )
            .at("device")),
        }
    }
}

/// Magnetometer hard iron offset (response). Current magnetometer hard iron offset.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagHardIronOffsetResponse {
    /// X, Y, Z hard iron offset in the sensor frame. Units: gauss.
    pub offset: [f32; 3],
}

impl Default for MagHardIronOffsetResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagHardIronOffsetResponse {
    const ZERO: Self = Self {
        offset: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_offset = <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("offset"))?;
        Ok(Self { offset: p_offset })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.offset;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("offset"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.offset;
        crate::json::key(w, &mut first, "offset")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagHardIronOffsetResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["offset"])?;
        let p_offset = o.req(
            "offset",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { offset: p_offset })
    }
}

impl MagHardIronOffsetResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for MagHardIronOffsetResponse {
    const DESCRIPTOR: u8 = 0x9C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "mag_hard_iron_offset_response";
}

/// Magnetometer soft iron matrix. Layout for device gx5_45.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagSoftIronMatrixGx5_45 {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Soft iron matrix m11..m33, row-major (dimensionless). Sent for: write, write_no_ack.
    pub matrix: Option<[f32; 9]>,
}

impl Default for MagSoftIronMatrixGx5_45 {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagSoftIronMatrixGx5_45 {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        matrix: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_matrix = if r.left() > 0 {
            Some(<[f32; 9] as crate::wire::Wire>::decode(r).map_err(|e| e.at("matrix"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            matrix: p_matrix,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.matrix {
            optionals.present("matrix")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("matrix"))?;
        } else {
            optionals.absent("matrix");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.matrix {
            crate::json::key(w, &mut first, "matrix")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagSoftIronMatrixGx5_45 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "matrix"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_matrix = o.opt(
            "matrix",
            <[f32; 9] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            matrix: p_matrix,
        })
    }
}

impl MagSoftIronMatrixGx5_45 {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for MagSoftIronMatrixGx5_45 {
    const DESCRIPTOR: u8 = 0x3B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "mag_soft_iron_matrix";
}

/// Magnetometer soft iron matrix. Layout for device cv7_ins.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagSoftIronMatrixCv7Ins {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Soft iron matrix, row-major (dimensionless). Sent for: write.
    pub matrix: Option<[f32; 9]>,
}

impl Default for MagSoftIronMatrixCv7Ins {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagSoftIronMatrixCv7Ins {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        matrix: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_matrix = if r.left() > 0 {
            Some(<[f32; 9] as crate::wire::Wire>::decode(r).map_err(|e| e.at("matrix"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            matrix: p_matrix,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.matrix {
            optionals.present("matrix")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("matrix"))?;
        } else {
            optionals.absent("matrix");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.matrix {
            crate::json::key(w, &mut first, "matrix")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagSoftIronMatrixCv7Ins {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "matrix"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_matrix = o.opt(
            "matrix",
            <[f32; 9] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            matrix: p_matrix,
        })
    }
}

impl MagSoftIronMatrixCv7Ins {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for MagSoftIronMatrixCv7Ins {
    const DESCRIPTOR: u8 = 0x3B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "mag_soft_iron_matrix";
}

/// Magnetometer soft iron matrix. User magnetometer soft iron compensation matrix (row-major), applied to the scaled magnetometer output. Determined from calibration data after installation. Default: identity.
///
/// The layout differs per device; one variant per device, in spec order.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MagSoftIronMatrix {
    /// Layout for device `gx5_45`.
    Gx5_45(MagSoftIronMatrixGx5_45),
    /// Layout for device `cv7_ins`.
    Cv7Ins(MagSoftIronMatrixCv7Ins),
}

impl MagSoftIronMatrix {
    /// Field descriptor.
    pub const DESCRIPTOR: u8 = 0x3B;
    /// Field name as printed in JSON.
    pub const NAME: &'static str = "mag_soft_iron_matrix";

    /// Device whose layout this value uses.
    pub fn device(&self) -> crate::Device {
        match self {
            Self::Gx5_45(_) => crate::Device::Gx5_45,
            Self::Cv7Ins(_) => crate::Device::Cv7Ins,
        }
    }

    /// Decodes with `device`'s layout if it has one, else tries the layouts in spec order and
    /// keeps the first that decodes (reporting the first layout's error if none does).
    pub fn decode_data(
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Result<Self, crate::error::DecodeError> {
        if device == Some(crate::Device::Gx5_45) {
            return <MagSoftIronMatrixGx5_45 as crate::wire::Layout>::decode_data(data)
                .map(Self::Gx5_45);
        }
        if device == Some(crate::Device::Cv7Ins) {
            return <MagSoftIronMatrixCv7Ins as crate::wire::Layout>::decode_data(data)
                .map(Self::Cv7Ins);
        }
        let first = match <MagSoftIronMatrixGx5_45 as crate::wire::Layout>::decode_data(data) {
            Ok(v) => return Ok(Self::Gx5_45(v)),
            Err(e) => e,
        };
        if let Ok(v) = <MagSoftIronMatrixCv7Ins as crate::wire::Layout>::decode_data(data) {
            return Ok(Self::Cv7Ins(v));
        }
        Err(first)
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Gx5_45(v) => crate::wire::Layout::encode_data(v, w),
            Self::Cv7Ins(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Gx5_45(v) => crate::wire::Wire::write_json(v, w),
            Self::Cv7Ins(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the values of `device`'s layout.
    #[cfg(feature = "std")]
    pub fn from_json(
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        match device {
            Some(crate::Device::Gx5_45) => <MagSoftIronMatrixGx5_45 as crate::json_read::FromJson>::from_json(values)
                .map(Self::Gx5_45)
                .map_err(|e| e.at("values")),
            Some(crate::Device::Cv7Ins) => <MagSoftIronMatrixCv7Ins as crate::json_read::FromJson>::from_json(values)
                .map(Self::Cv7Ins)
                .map_err(|e| e.at("values")),
            None => Err(crate::json_read::JsonError::new(
                "field mag_soft_iron_matrix has per-device layouts; name one with \"device\" (gx5_45, cv7_ins)",
            )
            .at("device")),
        }
    }
}

/// Magnetometer soft iron matrix (response). Current magnetometer soft iron matrix, row-major.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MagSoftIronMatrixResponse {
    /// Soft iron matrix, row-major (dimensionless).
    pub matrix: [f32; 9],
}

impl Default for MagSoftIronMatrixResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MagSoftIronMatrixResponse {
    const ZERO: Self = Self {
        matrix: <[f32; 9] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(36);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_matrix = <[f32; 9] as crate::wire::Wire>::decode(r).map_err(|e| e.at("matrix"))?;
        Ok(Self { matrix: p_matrix })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.matrix;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("matrix"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.matrix;
        crate::json::key(w, &mut first, "matrix")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MagSoftIronMatrixResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["matrix"])?;
        let p_matrix = o.req(
            "matrix",
            <[f32; 9] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { matrix: p_matrix })
    }
}

impl MagSoftIronMatrixResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for MagSoftIronMatrixResponse {
    const DESCRIPTOR: u8 = 0x9D;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "mag_soft_iron_matrix_response";
}

/// Coning and sculling enable. Enable or disable coning and sculling compensation (enabled by default).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConingScullingEnable {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// True enables coning and sculling compensation (0x01), false disables it (0x00). Sent for: write.
    pub enable: Option<bool>,
}

impl Default for ConingScullingEnable {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ConingScullingEnable {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        enable: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_enable = if r.left() > 0 {
            Some(<bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            enable: p_enable,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.enable {
            optionals.present("enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        } else {
            optionals.absent("enable");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.enable {
            crate::json::key(w, &mut first, "enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ConingScullingEnable {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "enable"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.opt("enable", <bool as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            enable: p_enable,
        })
    }
}

impl ConingScullingEnable {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for ConingScullingEnable {
    const DESCRIPTOR: u8 = 0x3E;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "coning_sculling_enable";
}

/// Coning and sculling enable (response). Current coning and sculling compensation setting.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConingScullingEnableResponse {
    /// True if coning and sculling compensation is enabled.
    pub enable: bool,
}

impl Default for ConingScullingEnableResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ConingScullingEnableResponse {
    const ZERO: Self = Self {
        enable: <bool as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_enable = <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?;
        Ok(Self { enable: p_enable })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.enable;
        crate::json::key(w, &mut first, "enable")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ConingScullingEnableResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["enable"])?;
        let p_enable = o.req("enable", <bool as crate::json_read::FromJson>::from_json)?;
        Ok(Self { enable: p_enable })
    }
}

impl ConingScullingEnableResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for ConingScullingEnableResponse {
    const DESCRIPTOR: u8 = 0x9E;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "coning_sculling_enable_response";
}

/// UART baud rate. Baud rate of the main communication port (UART1). The ack is sent at the old rate; the new rate applies after pending data is sent (up to 250 ms). Send it alone, with the device idle, and wait 250 ms. GX5-45 rates: 9600, 19200, 115200 (default), 230400, 460800, 921600.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UartBaudrate {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// New baud rate; must be a rate the device supports. Units: bit/s. Sent for: write.
    pub baud: Option<u32>,
}

impl Default for UartBaudrate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for UartBaudrate {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        baud: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_baud = if r.left() > 0 {
            Some(<u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("baud"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            baud: p_baud,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.baud {
            optionals.present("baud")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("baud"))?;
        } else {
            optionals.absent("baud");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.baud {
            crate::json::key(w, &mut first, "baud")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for UartBaudrate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "baud"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_baud = o.opt("baud", <u32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            baud: p_baud,
        })
    }
}

impl UartBaudrate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for UartBaudrate {
    const DESCRIPTOR: u8 = 0x40;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "uart_baudrate";
}

/// UART baud rate (response). Current baud rate of the main port.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UartBaudrateResponse {
    /// Current baud rate. Units: bit/s.
    pub baud: u32,
}

impl Default for UartBaudrateResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for UartBaudrateResponse {
    const ZERO: Self = Self {
        baud: <u32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(4);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_baud = <u32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("baud"))?;
        Ok(Self { baud: p_baud })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.baud;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("baud"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.baud;
        crate::json::key(w, &mut first, "baud")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for UartBaudrateResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["baud"])?;
        let p_baud = o.req("baud", <u32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { baud: p_baud })
    }
}

impl UartBaudrateResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for UartBaudrateResponse {
    const DESCRIPTOR: u8 = 0x87;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "uart_baudrate_response";
}

/// GPIO configuration. Configure a user GPIO pin: the feature it serves, its behavior within that feature, and its electrical mode. Features and pin modes are pin- and device-dependent (User GPIO, line 1272). Configure an output feature before the pin (to avoid glitches) and an input pin before its feature. Features limited to one pin move to the most recently configured pin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpioConfig {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// GPIO pin number from 1; 0 selects all pins for save, load and default. Sent for: write, read, save, load, default.
    pub pin: u8,
    /// What the pin is used for. Sent for: write.
    pub feature: Option<crate::types::GpioFeature>,
    /// Role of the pin within the feature (meaning depends on feature). Sent for: write.
    pub behavior: Option<crate::types::GpioBehavior>,
    /// Electrical mode of the pin. Sent for: write.
    pub pin_mode: Option<crate::types::GpioPinMode>,
}

impl Default for GpioConfig {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpioConfig {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        pin: <u8 as crate::wire::Wire>::ZERO,
        feature: None,
        behavior: None,
        pin_mode: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_pin = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pin"))?;
        let p_feature = if r.left() > 0 {
            Some(
                <crate::types::GpioFeature as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("feature"))?,
            )
        } else {
            None
        };
        let p_behavior = if r.left() > 0 {
            Some(
                crate::types::GpioBehavior::decode_selected(r, p_feature.map_or(0, |s| s.0))
                    .map_err(|e| e.at("behavior"))?,
            )
        } else {
            None
        };
        let p_pin_mode = if r.left() > 0 {
            Some(
                <crate::types::GpioPinMode as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("pin_mode"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            pin: p_pin,
            feature: p_feature,
            behavior: p_behavior,
            pin_mode: p_pin_mode,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.pin;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pin"))?;
        if let Some(v) = &self.feature {
            optionals.present("feature")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("feature"))?;
        } else {
            optionals.absent("feature");
        }
        if let Some(v) = &self.behavior {
            optionals.present("behavior")?;
            v.encode_selected(w, self.feature.map_or(0, |s| s.0))
                .map_err(|e| e.at("behavior"))?;
        } else {
            optionals.absent("behavior");
        }
        if let Some(v) = &self.pin_mode {
            optionals.present("pin_mode")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("pin_mode"))?;
        } else {
            optionals.absent("pin_mode");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pin;
        crate::json::key(w, &mut first, "pin")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.feature {
            crate::json::key(w, &mut first, "feature")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.behavior {
            crate::json::key(w, &mut first, "behavior")?;
            v.write_json(w)?;
        }
        if let Some(v) = &self.pin_mode {
            crate::json::key(w, &mut first, "pin_mode")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpioConfig {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o =
            crate::json_read::Obj::new(v, &["function", "pin", "feature", "behavior", "pin_mode"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_pin = o.req("pin", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_feature = o.opt(
            "feature",
            <crate::types::GpioFeature as crate::json_read::FromJson>::from_json,
        )?;
        let p_behavior = o.opt("behavior", |v| {
            crate::types::GpioBehavior::from_json_selected(v, p_feature.map_or(0, |s| s.0))
        })?;
        let p_pin_mode = o.opt(
            "pin_mode",
            <crate::types::GpioPinMode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            pin: p_pin,
            feature: p_feature,
            behavior: p_behavior,
            pin_mode: p_pin_mode,
        })
    }
}

impl GpioConfig {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GpioConfig {
    const DESCRIPTOR: u8 = 0x41;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gpio_config";
}

/// GPIO configuration (response). Current configuration of a GPIO pin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpioConfigResponse {
    /// GPIO pin number from 1.
    pub pin: u8,
    /// What the pin is used for.
    pub feature: crate::types::GpioFeature,
    /// Role of the pin within the feature.
    pub behavior: crate::types::GpioBehavior,
    /// Electrical mode of the pin.
    pub pin_mode: crate::types::GpioPinMode,
}

impl Default for GpioConfigResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpioConfigResponse {
    const ZERO: Self = Self {
        pin: <u8 as crate::wire::Wire>::ZERO,
        feature: <crate::types::GpioFeature as crate::wire::Wire>::ZERO,
        behavior: crate::types::GpioBehavior::ZERO,
        pin_mode: <crate::types::GpioPinMode as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_pin = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pin"))?;
        let p_feature = <crate::types::GpioFeature as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("feature"))?;
        let p_behavior = crate::types::GpioBehavior::decode_selected(r, p_feature.0)
            .map_err(|e| e.at("behavior"))?;
        let p_pin_mode = <crate::types::GpioPinMode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("pin_mode"))?;
        Ok(Self {
            pin: p_pin,
            feature: p_feature,
            behavior: p_behavior,
            pin_mode: p_pin_mode,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.pin;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pin"))?;
        let v = &self.feature;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("feature"))?;
        let v = &self.behavior;
        v.encode_selected(w, self.feature.0)
            .map_err(|e| e.at("behavior"))?;
        let v = &self.pin_mode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pin_mode"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.pin;
        crate::json::key(w, &mut first, "pin")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.feature;
        crate::json::key(w, &mut first, "feature")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.behavior;
        crate::json::key(w, &mut first, "behavior")?;
        v.write_json(w)?;
        let v = &self.pin_mode;
        crate::json::key(w, &mut first, "pin_mode")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpioConfigResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["pin", "feature", "behavior", "pin_mode"])?;
        let p_pin = o.req("pin", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_feature = o.req(
            "feature",
            <crate::types::GpioFeature as crate::json_read::FromJson>::from_json,
        )?;
        let p_behavior = o.req("behavior", |v| {
            crate::types::GpioBehavior::from_json_selected(v, p_feature.0)
        })?;
        let p_pin_mode = o.req(
            "pin_mode",
            <crate::types::GpioPinMode as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            pin: p_pin,
            feature: p_feature,
            behavior: p_behavior,
            pin_mode: p_pin_mode,
        })
    }
}

impl GpioConfigResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GpioConfigResponse {
    const DESCRIPTOR: u8 = 0xC1;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gpio_config_response";
}

/// GPIO state. Read the physical state of a pin or set its output state. Setting has a visible effect only when the pin is an output; save, load and default are not supported (use 0x0C,0x41 to set the initial state).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpioState {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// GPIO pin number from 1 (not 0). Sent for: write, read.
    pub pin: u8,
    /// Pin state (true = high). Sent for: write.
    pub state: Option<bool>,
}

impl Default for GpioState {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpioState {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        pin: <u8 as crate::wire::Wire>::ZERO,
        state: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_pin = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pin"))?;
        let p_state = if r.left() > 0 {
            Some(<bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("state"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            pin: p_pin,
            state: p_state,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.pin;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pin"))?;
        if let Some(v) = &self.state {
            optionals.present("state")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("state"))?;
        } else {
            optionals.absent("state");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pin;
        crate::json::key(w, &mut first, "pin")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.state {
            crate::json::key(w, &mut first, "state")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpioState {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "pin", "state"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_pin = o.req("pin", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_state = o.opt("state", <bool as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            pin: p_pin,
            state: p_state,
        })
    }
}

impl GpioState {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GpioState {
    const DESCRIPTOR: u8 = 0x42;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gpio_state";
}

/// GPIO state (response). Physical state of a pin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpioStateResponse {
    /// GPIO pin number from 1.
    pub pin: u8,
    /// Pin state (true = high).
    pub state: bool,
}

impl Default for GpioStateResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GpioStateResponse {
    const ZERO: Self = Self {
        pin: <u8 as crate::wire::Wire>::ZERO,
        state: <bool as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_pin = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pin"))?;
        let p_state = <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("state"))?;
        Ok(Self {
            pin: p_pin,
            state: p_state,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.pin;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pin"))?;
        let v = &self.state;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("state"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.pin;
        crate::json::key(w, &mut first, "pin")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.state;
        crate::json::key(w, &mut first, "state")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GpioStateResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["pin", "state"])?;
        let p_pin = o.req("pin", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_state = o.req("state", <bool as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            pin: p_pin,
            state: p_state,
        })
    }
}

impl GpioStateResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GpioStateResponse {
    const DESCRIPTOR: u8 = 0xC2;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gpio_state_response";
}

/// Odometer configuration. Configure the hardware odometer (wheel encoder) interface: mode, scale factor and its uncertainty. Distance = pulses / scaling.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OdometerConfig {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Odometer mode. Sent for: write.
    pub mode: Option<crate::types::OdometerMode>,
    /// Encoder pulses per metre (N / (2 pi R), N pulses per revolution, R wheel radius); negative if the encoder turns backwards. Units: pulses/m. Sent for: write.
    pub scaling: Option<f32>,
    /// 1-sigma uncertainty of the pulses-to-distance scale. Units: m/m. Sent for: write.
    pub uncertainty: Option<f32>,
}

impl Default for OdometerConfig {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for OdometerConfig {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        mode: None,
        scaling: None,
        uncertainty: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_mode = if r.left() > 0 {
            Some(
                <crate::types::OdometerMode as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("mode"))?,
            )
        } else {
            None
        };
        let p_scaling = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("scaling"))?)
        } else {
            None
        };
        let p_uncertainty = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("uncertainty"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            mode: p_mode,
            scaling: p_scaling,
            uncertainty: p_uncertainty,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.mode {
            optionals.present("mode")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("mode"))?;
        } else {
            optionals.absent("mode");
        }
        if let Some(v) = &self.scaling {
            optionals.present("scaling")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("scaling"))?;
        } else {
            optionals.absent("scaling");
        }
        if let Some(v) = &self.uncertainty {
            optionals.present("uncertainty")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("uncertainty"))?;
        } else {
            optionals.absent("uncertainty");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.mode {
            crate::json::key(w, &mut first, "mode")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.scaling {
            crate::json::key(w, &mut first, "scaling")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.uncertainty {
            crate::json::key(w, &mut first, "uncertainty")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for OdometerConfig {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "mode", "scaling", "uncertainty"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_mode = o.opt(
            "mode",
            <crate::types::OdometerMode as crate::json_read::FromJson>::from_json,
        )?;
        let p_scaling = o.opt("scaling", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_uncertainty = o.opt(
            "uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            mode: p_mode,
            scaling: p_scaling,
            uncertainty: p_uncertainty,
        })
    }
}

impl OdometerConfig {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for OdometerConfig {
    const DESCRIPTOR: u8 = 0x43;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "odometer_config";
}

/// Odometer configuration (response). Current odometer configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OdometerConfigResponse {
    /// Odometer mode.
    pub mode: crate::types::OdometerMode,
    /// Encoder pulses per metre. Units: pulses/m.
    pub scaling: f32,
    /// 1-sigma uncertainty of the scale. Units: m/m.
    pub uncertainty: f32,
}

impl Default for OdometerConfigResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for OdometerConfigResponse {
    const ZERO: Self = Self {
        mode: <crate::types::OdometerMode as crate::wire::Wire>::ZERO,
        scaling: <f32 as crate::wire::Wire>::ZERO,
        uncertainty: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(9);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_mode = <crate::types::OdometerMode as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("mode"))?;
        let p_scaling = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("scaling"))?;
        let p_uncertainty =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("uncertainty"))?;
        Ok(Self {
            mode: p_mode,
            scaling: p_scaling,
            uncertainty: p_uncertainty,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.mode;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("mode"))?;
        let v = &self.scaling;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scaling"))?;
        let v = &self.uncertainty;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("uncertainty"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.mode;
        crate::json::key(w, &mut first, "mode")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.scaling;
        crate::json::key(w, &mut first, "scaling")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.uncertainty;
        crate::json::key(w, &mut first, "uncertainty")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for OdometerConfigResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["mode", "scaling", "uncertainty"])?;
        let p_mode = o.req(
            "mode",
            <crate::types::OdometerMode as crate::json_read::FromJson>::from_json,
        )?;
        let p_scaling = o.req("scaling", <f32 as crate::json_read::FromJson>::from_json)?;
        let p_uncertainty = o.req(
            "uncertainty",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            mode: p_mode,
            scaling: p_scaling,
            uncertainty: p_uncertainty,
        })
    }
}

impl OdometerConfigResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for OdometerConfigResponse {
    const DESCRIPTOR: u8 = 0xC3;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "odometer_config_response";
}

/// Advanced low-pass filter settings. Per-quantity IIR low-pass filter on the scaled IMU data (0x80: accel 0x04, gyro 0x05, mag 0x06, pressure 0x17): bypass it, or set its -3 dB cutoff manually instead of half the reporting rate. Deprecated on the CV7 in favour of 0x0C,0x54.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdvancedLowpassFilter {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Field descriptor in the sensor set (0x80) of the filtered quantity; 0 = all (CV7, not for read). Sent for: write, read, save, load, default.
    pub target_descriptor: u8,
    /// Apply the low-pass filter. Sent for: write.
    pub enable: Option<bool>,
    /// Use the cutoff given below; false sets it to half the reporting rate. Sent for: write.
    pub manual: Option<bool>,
    /// -3 dB cutoff frequency (at most 250 Hz on GX5-45); ignored when not manual. Units: Hz. Sent for: write.
    pub frequency: Option<u16>,
    /// Reserved, send 0. Sent for: write.
    pub reserved: Option<u8>,
}

impl Default for AdvancedLowpassFilter {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AdvancedLowpassFilter {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        target_descriptor: <u8 as crate::wire::Wire>::ZERO,
        enable: None,
        manual: None,
        frequency: None,
        reserved: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_target_descriptor =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("target_descriptor"))?;
        let p_enable = if r.left() > 0 {
            Some(<bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?)
        } else {
            None
        };
        let p_manual = if r.left() > 0 {
            Some(<bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("manual"))?)
        } else {
            None
        };
        let p_frequency = if r.left() > 0 {
            Some(<u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frequency"))?)
        } else {
            None
        };
        let p_reserved = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            target_descriptor: p_target_descriptor,
            enable: p_enable,
            manual: p_manual,
            frequency: p_frequency,
            reserved: p_reserved,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.target_descriptor;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("target_descriptor"))?;
        if let Some(v) = &self.enable {
            optionals.present("enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        } else {
            optionals.absent("enable");
        }
        if let Some(v) = &self.manual {
            optionals.present("manual")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("manual"))?;
        } else {
            optionals.absent("manual");
        }
        if let Some(v) = &self.frequency {
            optionals.present("frequency")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("frequency"))?;
        } else {
            optionals.absent("frequency");
        }
        if let Some(v) = &self.reserved {
            optionals.present("reserved")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved"))?;
        } else {
            optionals.absent("reserved");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.target_descriptor;
        crate::json::key(w, &mut first, "target_descriptor")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.enable {
            crate::json::key(w, &mut first, "enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.manual {
            crate::json::key(w, &mut first, "manual")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.frequency {
            crate::json::key(w, &mut first, "frequency")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.reserved {
            crate::json::key(w, &mut first, "reserved")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AdvancedLowpassFilter {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "function",
                "target_descriptor",
                "enable",
                "manual",
                "frequency",
                "reserved",
            ],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_target_descriptor = o.req(
            "target_descriptor",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.opt("enable", <bool as crate::json_read::FromJson>::from_json)?;
        let p_manual = o.opt("manual", <bool as crate::json_read::FromJson>::from_json)?;
        let p_frequency = o.opt("frequency", <u16 as crate::json_read::FromJson>::from_json)?;
        let p_reserved = o.opt("reserved", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            target_descriptor: p_target_descriptor,
            enable: p_enable,
            manual: p_manual,
            frequency: p_frequency,
            reserved: p_reserved,
        })
    }
}

impl AdvancedLowpassFilter {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for AdvancedLowpassFilter {
    const DESCRIPTOR: u8 = 0x50;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "advanced_lowpass_filter";
}

/// Advanced low-pass filter settings (response). Current low-pass filter settings of one quantity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdvancedLowpassFilterResponse {
    /// Field descriptor of the filtered quantity.
    pub target_descriptor: u8,
    /// True if the filter is enabled.
    pub enable: bool,
    /// True if the cutoff was set manually.
    pub manual: bool,
    /// -3 dB cutoff frequency (unspecified in automatic mode). Units: Hz.
    pub frequency: u16,
    /// Reserved; ignore.
    pub reserved: u8,
}

impl Default for AdvancedLowpassFilterResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for AdvancedLowpassFilterResponse {
    const ZERO: Self = Self {
        target_descriptor: <u8 as crate::wire::Wire>::ZERO,
        enable: <bool as crate::wire::Wire>::ZERO,
        manual: <bool as crate::wire::Wire>::ZERO,
        frequency: <u16 as crate::wire::Wire>::ZERO,
        reserved: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(6);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_target_descriptor =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("target_descriptor"))?;
        let p_enable = <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?;
        let p_manual = <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("manual"))?;
        let p_frequency = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frequency"))?;
        let p_reserved = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved"))?;
        Ok(Self {
            target_descriptor: p_target_descriptor,
            enable: p_enable,
            manual: p_manual,
            frequency: p_frequency,
            reserved: p_reserved,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.target_descriptor;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("target_descriptor"))?;
        let v = &self.enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        let v = &self.manual;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("manual"))?;
        let v = &self.frequency;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frequency"))?;
        let v = &self.reserved;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.target_descriptor;
        crate::json::key(w, &mut first, "target_descriptor")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.enable;
        crate::json::key(w, &mut first, "enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.manual;
        crate::json::key(w, &mut first, "manual")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frequency;
        crate::json::key(w, &mut first, "frequency")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved;
        crate::json::key(w, &mut first, "reserved")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for AdvancedLowpassFilterResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "target_descriptor",
                "enable",
                "manual",
                "frequency",
                "reserved",
            ],
        )?;
        let p_target_descriptor = o.req(
            "target_descriptor",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.req("enable", <bool as crate::json_read::FromJson>::from_json)?;
        let p_manual = o.req("manual", <bool as crate::json_read::FromJson>::from_json)?;
        let p_frequency = o.req("frequency", <u16 as crate::json_read::FromJson>::from_json)?;
        let p_reserved = o.req("reserved", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            target_descriptor: p_target_descriptor,
            enable: p_enable,
            manual: p_manual,
            frequency: p_frequency,
            reserved: p_reserved,
        })
    }
}

impl AdvancedLowpassFilterResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for AdvancedLowpassFilterResponse {
    const DESCRIPTOR: u8 = 0x8B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "advanced_lowpass_filter_response";
}

/// Complementary filter settings. Configure the AHRS complementary filter behind the 0x80 attitude outputs (matrix 0x09, quaternion 0x0A, Euler 0x0C): pitch/roll correction from the accelerometer (GX5-45: "up compensation") and heading correction from the magnetometer ("north compensation"), each with a time constant of 1 to 1000 s (default 10 s; out-of-range values are NACK'd).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ComplementaryFilter {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Enable pitch/roll (up) correction. Sent for: write.
    pub pitch_roll_enable: Option<bool>,
    /// Enable heading (north) correction; needs a magnetometer. Sent for: write.
    pub heading_enable: Option<bool>,
    /// Time constant of the pitch/roll correction. Units: s. Sent for: write.
    pub pitch_roll_time_constant: Option<f32>,
    /// Time constant of the heading correction. Units: s. Sent for: write.
    pub heading_time_constant: Option<f32>,
}

impl Default for ComplementaryFilter {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ComplementaryFilter {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        pitch_roll_enable: None,
        heading_enable: None,
        pitch_roll_time_constant: None,
        heading_time_constant: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_pitch_roll_enable = if r.left() > 0 {
            Some(<bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("pitch_roll_enable"))?)
        } else {
            None
        };
        let p_heading_enable = if r.left() > 0 {
            Some(<bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading_enable"))?)
        } else {
            None
        };
        let p_pitch_roll_time_constant = if r.left() > 0 {
            Some(
                <f32 as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("pitch_roll_time_constant"))?,
            )
        } else {
            None
        };
        let p_heading_time_constant = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading_time_constant"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            pitch_roll_enable: p_pitch_roll_enable,
            heading_enable: p_heading_enable,
            pitch_roll_time_constant: p_pitch_roll_time_constant,
            heading_time_constant: p_heading_time_constant,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.pitch_roll_enable {
            optionals.present("pitch_roll_enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("pitch_roll_enable"))?;
        } else {
            optionals.absent("pitch_roll_enable");
        }
        if let Some(v) = &self.heading_enable {
            optionals.present("heading_enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading_enable"))?;
        } else {
            optionals.absent("heading_enable");
        }
        if let Some(v) = &self.pitch_roll_time_constant {
            optionals.present("pitch_roll_time_constant")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("pitch_roll_time_constant"))?;
        } else {
            optionals.absent("pitch_roll_time_constant");
        }
        if let Some(v) = &self.heading_time_constant {
            optionals.present("heading_time_constant")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading_time_constant"))?;
        } else {
            optionals.absent("heading_time_constant");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.pitch_roll_enable {
            crate::json::key(w, &mut first, "pitch_roll_enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.heading_enable {
            crate::json::key(w, &mut first, "heading_enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.pitch_roll_time_constant {
            crate::json::key(w, &mut first, "pitch_roll_time_constant")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.heading_time_constant {
            crate::json::key(w, &mut first, "heading_time_constant")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ComplementaryFilter {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "function",
                "pitch_roll_enable",
                "heading_enable",
                "pitch_roll_time_constant",
                "heading_time_constant",
            ],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_pitch_roll_enable = o.opt(
            "pitch_roll_enable",
            <bool as crate::json_read::FromJson>::from_json,
        )?;
        let p_heading_enable = o.opt(
            "heading_enable",
            <bool as crate::json_read::FromJson>::from_json,
        )?;
        let p_pitch_roll_time_constant = o.opt(
            "pitch_roll_time_constant",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_heading_time_constant = o.opt(
            "heading_time_constant",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            pitch_roll_enable: p_pitch_roll_enable,
            heading_enable: p_heading_enable,
            pitch_roll_time_constant: p_pitch_roll_time_constant,
            heading_time_constant: p_heading_time_constant,
        })
    }
}

impl ComplementaryFilter {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for ComplementaryFilter {
    const DESCRIPTOR: u8 = 0x51;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "complementary_filter";
}

/// Complementary filter settings (response). Current complementary filter settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ComplementaryFilterResponse {
    /// Pitch/roll (up) correction enabled.
    pub pitch_roll_enable: bool,
    /// Heading (north) correction enabled.
    pub heading_enable: bool,
    /// Time constant of the pitch/roll correction. Units: s.
    pub pitch_roll_time_constant: f32,
    /// Time constant of the heading correction. Units: s.
    pub heading_time_constant: f32,
}

impl Default for ComplementaryFilterResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ComplementaryFilterResponse {
    const ZERO: Self = Self {
        pitch_roll_enable: <bool as crate::wire::Wire>::ZERO,
        heading_enable: <bool as crate::wire::Wire>::ZERO,
        pitch_roll_time_constant: <f32 as crate::wire::Wire>::ZERO,
        heading_time_constant: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(10);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_pitch_roll_enable =
            <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("pitch_roll_enable"))?;
        let p_heading_enable =
            <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading_enable"))?;
        let p_pitch_roll_time_constant =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("pitch_roll_time_constant"))?;
        let p_heading_time_constant =
            <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("heading_time_constant"))?;
        Ok(Self {
            pitch_roll_enable: p_pitch_roll_enable,
            heading_enable: p_heading_enable,
            pitch_roll_time_constant: p_pitch_roll_time_constant,
            heading_time_constant: p_heading_time_constant,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.pitch_roll_enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pitch_roll_enable"))?;
        let v = &self.heading_enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading_enable"))?;
        let v = &self.pitch_roll_time_constant;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("pitch_roll_time_constant"))?;
        let v = &self.heading_time_constant;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("heading_time_constant"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.pitch_roll_enable;
        crate::json::key(w, &mut first, "pitch_roll_enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.heading_enable;
        crate::json::key(w, &mut first, "heading_enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.pitch_roll_time_constant;
        crate::json::key(w, &mut first, "pitch_roll_time_constant")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.heading_time_constant;
        crate::json::key(w, &mut first, "heading_time_constant")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ComplementaryFilterResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "pitch_roll_enable",
                "heading_enable",
                "pitch_roll_time_constant",
                "heading_time_constant",
            ],
        )?;
        let p_pitch_roll_enable = o.req(
            "pitch_roll_enable",
            <bool as crate::json_read::FromJson>::from_json,
        )?;
        let p_heading_enable = o.req(
            "heading_enable",
            <bool as crate::json_read::FromJson>::from_json,
        )?;
        let p_pitch_roll_time_constant = o.req(
            "pitch_roll_time_constant",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        let p_heading_time_constant = o.req(
            "heading_time_constant",
            <f32 as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            pitch_roll_enable: p_pitch_roll_enable,
            heading_enable: p_heading_enable,
            pitch_roll_time_constant: p_pitch_roll_time_constant,
            heading_time_constant: p_heading_time_constant,
        })
    }
}

impl ComplementaryFilterResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for ComplementaryFilterResponse {
    const DESCRIPTOR: u8 = 0x97;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "complementary_filter_response";
}

/// Sensor range. Select the range (gain) of an IMU sensor; the setting values come from Get Calibrated Sensor Ranges (0x0C,0x53). Other values may be NACK'd or give inaccurate data.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorRange {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Sensor to configure; all only for save, load and default. Sent for: write, read, save, load, default.
    pub sensor: crate::types::SensorRangeType,
    /// Range setting value (from 0x0C,0x53). Sent for: write.
    pub setting: Option<u8>,
}

impl Default for SensorRange {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorRange {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        sensor: <crate::types::SensorRangeType as crate::wire::Wire>::ZERO,
        setting: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_sensor = <crate::types::SensorRangeType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("sensor"))?;
        let p_setting = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("setting"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            sensor: p_sensor,
            setting: p_setting,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.sensor;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sensor"))?;
        if let Some(v) = &self.setting {
            optionals.present("setting")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("setting"))?;
        } else {
            optionals.absent("setting");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.sensor;
        crate::json::key(w, &mut first, "sensor")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.setting {
            crate::json::key(w, &mut first, "setting")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorRange {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "sensor", "setting"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_sensor = o.req(
            "sensor",
            <crate::types::SensorRangeType as crate::json_read::FromJson>::from_json,
        )?;
        let p_setting = o.opt("setting", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            sensor: p_sensor,
            setting: p_setting,
        })
    }
}

impl SensorRange {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for SensorRange {
    const DESCRIPTOR: u8 = 0x52;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "sensor_range";
}

/// Sensor range (response). Current range setting of a sensor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorRangeResponse {
    /// Sensor.
    pub sensor: crate::types::SensorRangeType,
    /// Range setting value.
    pub setting: u8,
}

impl Default for SensorRangeResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SensorRangeResponse {
    const ZERO: Self = Self {
        sensor: <crate::types::SensorRangeType as crate::wire::Wire>::ZERO,
        setting: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_sensor = <crate::types::SensorRangeType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("sensor"))?;
        let p_setting = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("setting"))?;
        Ok(Self {
            sensor: p_sensor,
            setting: p_setting,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.sensor;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sensor"))?;
        let v = &self.setting;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("setting"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.sensor;
        crate::json::key(w, &mut first, "sensor")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.setting;
        crate::json::key(w, &mut first, "setting")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SensorRangeResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["sensor", "setting"])?;
        let p_sensor = o.req(
            "sensor",
            <crate::types::SensorRangeType as crate::json_read::FromJson>::from_json,
        )?;
        let p_setting = o.req("setting", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            sensor: p_sensor,
            setting: p_setting,
        })
    }
}

impl SensorRangeResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for SensorRangeResponse {
    const DESCRIPTOR: u8 = 0xD2;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "sensor_range_response";
}

/// Get calibrated sensor ranges. List the range settings a sensor supports, for use with Sensor Range (0x0C,0x52).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetCalibratedSensorRanges {
    /// Sensor to query (not all).
    pub sensor: crate::types::SensorRangeType,
}

impl Default for GetCalibratedSensorRanges {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetCalibratedSensorRanges {
    const ZERO: Self = Self {
        sensor: <crate::types::SensorRangeType as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_sensor = <crate::types::SensorRangeType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("sensor"))?;
        Ok(Self { sensor: p_sensor })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.sensor;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sensor"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.sensor;
        crate::json::key(w, &mut first, "sensor")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GetCalibratedSensorRanges {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["sensor"])?;
        let p_sensor = o.req(
            "sensor",
            <crate::types::SensorRangeType as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { sensor: p_sensor })
    }
}

impl GetCalibratedSensorRanges {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GetCalibratedSensorRanges {
    const DESCRIPTOR: u8 = 0x53;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "get_calibrated_sensor_ranges";
}

/// Calibrated sensor ranges. Supported range settings of a sensor, each with its full-scale value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CalibratedSensorRanges {
    /// Sensor from the command.
    pub sensor: crate::types::SensorRangeType,
    /// Number of supported ranges.
    pub num_ranges: u8,
    /// Supported (setting, range) pairs.
    pub ranges: crate::bounded::BoundedVec<crate::types::SensorRangeEntry, 50>,
}

impl Default for CalibratedSensorRanges {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for CalibratedSensorRanges {
    const ZERO: Self = Self {
        sensor: <crate::types::SensorRangeType as crate::wire::Wire>::ZERO,
        num_ranges: <u8 as crate::wire::Wire>::ZERO,
        ranges: <crate::bounded::BoundedVec<crate::types::SensorRangeEntry, 50> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_sensor = <crate::types::SensorRangeType as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("sensor"))?;
        let p_num_ranges = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_ranges"))?;
        let p_ranges =
            crate::bounded::BoundedVec::<crate::types::SensorRangeEntry, 50>::decode_counted(
                r,
                u64::from(p_num_ranges),
            )
            .map_err(|e| e.at("ranges"))?;
        Ok(Self {
            sensor: p_sensor,
            num_ranges: p_num_ranges,
            ranges: p_ranges,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.sensor;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sensor"))?;
        let v = &self.num_ranges;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_ranges"))?;
        let v = &self.ranges;
        v.encode_counted(w, u64::from(self.num_ranges))
            .map_err(|e| e.at("ranges"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.sensor;
        crate::json::key(w, &mut first, "sensor")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.num_ranges;
        crate::json::key(w, &mut first, "num_ranges")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.ranges;
        crate::json::key(w, &mut first, "ranges")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for CalibratedSensorRanges {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["sensor", "num_ranges", "ranges"])?;
        let p_sensor = o.req(
            "sensor",
            <crate::types::SensorRangeType as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_ranges = o.req("num_ranges", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_ranges = o.req("ranges", <crate::bounded::BoundedVec<crate::types::SensorRangeEntry, 50> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            sensor: p_sensor,
            num_ranges: p_num_ranges,
            ranges: p_ranges,
        })
    }
}

impl CalibratedSensorRanges {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for CalibratedSensorRanges {
    const DESCRIPTOR: u8 = 0xD3;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "calibrated_sensor_ranges";
}

/// Low-pass anti-aliasing filter. Final low-pass (anti-aliasing) filter of a data quantity (CV7: scaled accel, gyro, mag and pressure in 0x80; compensated acceleration, angular rate and linear acceleration in 0x82). In automatic mode the cutoff tracks half the quantity's message rate (0x0C,0x0F). For write, save, load and default, descriptor set and/or field descriptor may be 0 for all (the field descriptor must be 0 if the set is 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LowpassFilter {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Descriptor set of the filtered quantity (0 = all, not for read). Sent for: write, read, save, load, default.
    pub desc_set: u8,
    /// Field descriptor of the filtered quantity (0 = all in the set, not for read). Sent for: write, read, save, load, default.
    pub field_desc: u8,
    /// Enable the filter. Sent for: write.
    pub enable: Option<bool>,
    /// Use the given frequency; false tracks half the message rate. Sent for: write.
    pub manual: Option<bool>,
    /// Cutoff frequency (read back in automatic mode: the actual cutoff). Units: Hz. Sent for: write.
    pub frequency: Option<f32>,
}

impl Default for LowpassFilter {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for LowpassFilter {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        desc_set: <u8 as crate::wire::Wire>::ZERO,
        field_desc: <u8 as crate::wire::Wire>::ZERO,
        enable: None,
        manual: None,
        frequency: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_desc_set = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("desc_set"))?;
        let p_field_desc = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("field_desc"))?;
        let p_enable = if r.left() > 0 {
            Some(<bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?)
        } else {
            None
        };
        let p_manual = if r.left() > 0 {
            Some(<bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("manual"))?)
        } else {
            None
        };
        let p_frequency = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frequency"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            desc_set: p_desc_set,
            field_desc: p_field_desc,
            enable: p_enable,
            manual: p_manual,
            frequency: p_frequency,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.desc_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("desc_set"))?;
        let v = &self.field_desc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("field_desc"))?;
        if let Some(v) = &self.enable {
            optionals.present("enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        } else {
            optionals.absent("enable");
        }
        if let Some(v) = &self.manual {
            optionals.present("manual")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("manual"))?;
        } else {
            optionals.absent("manual");
        }
        if let Some(v) = &self.frequency {
            optionals.present("frequency")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("frequency"))?;
        } else {
            optionals.absent("frequency");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.desc_set;
        crate::json::key(w, &mut first, "desc_set")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.field_desc;
        crate::json::key(w, &mut first, "field_desc")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.enable {
            crate::json::key(w, &mut first, "enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.manual {
            crate::json::key(w, &mut first, "manual")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.frequency {
            crate::json::key(w, &mut first, "frequency")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for LowpassFilter {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "function",
                "desc_set",
                "field_desc",
                "enable",
                "manual",
                "frequency",
            ],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_desc_set = o.req("desc_set", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_field_desc = o.req("field_desc", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_enable = o.opt("enable", <bool as crate::json_read::FromJson>::from_json)?;
        let p_manual = o.opt("manual", <bool as crate::json_read::FromJson>::from_json)?;
        let p_frequency = o.opt("frequency", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            desc_set: p_desc_set,
            field_desc: p_field_desc,
            enable: p_enable,
            manual: p_manual,
            frequency: p_frequency,
        })
    }
}

impl LowpassFilter {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for LowpassFilter {
    const DESCRIPTOR: u8 = 0x54;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "lowpass_filter";
}

/// Low-pass anti-aliasing filter (response). Current anti-aliasing filter settings of a quantity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LowpassFilterResponse {
    /// Descriptor set of the filtered quantity.
    pub desc_set: u8,
    /// Field descriptor of the filtered quantity.
    pub field_desc: u8,
    /// True if the filter is enabled.
    pub enable: bool,
    /// True if the frequency was set manually.
    pub manual: bool,
    /// Cutoff frequency (the actual one in automatic mode). Units: Hz.
    pub frequency: f32,
}

impl Default for LowpassFilterResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for LowpassFilterResponse {
    const ZERO: Self = Self {
        desc_set: <u8 as crate::wire::Wire>::ZERO,
        field_desc: <u8 as crate::wire::Wire>::ZERO,
        enable: <bool as crate::wire::Wire>::ZERO,
        manual: <bool as crate::wire::Wire>::ZERO,
        frequency: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(8);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_desc_set = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("desc_set"))?;
        let p_field_desc = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("field_desc"))?;
        let p_enable = <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?;
        let p_manual = <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("manual"))?;
        let p_frequency = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("frequency"))?;
        Ok(Self {
            desc_set: p_desc_set,
            field_desc: p_field_desc,
            enable: p_enable,
            manual: p_manual,
            frequency: p_frequency,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.desc_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("desc_set"))?;
        let v = &self.field_desc;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("field_desc"))?;
        let v = &self.enable;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        let v = &self.manual;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("manual"))?;
        let v = &self.frequency;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("frequency"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.desc_set;
        crate::json::key(w, &mut first, "desc_set")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.field_desc;
        crate::json::key(w, &mut first, "field_desc")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.enable;
        crate::json::key(w, &mut first, "enable")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.manual;
        crate::json::key(w, &mut first, "manual")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.frequency;
        crate::json::key(w, &mut first, "frequency")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for LowpassFilterResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["desc_set", "field_desc", "enable", "manual", "frequency"],
        )?;
        let p_desc_set = o.req("desc_set", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_field_desc = o.req("field_desc", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_enable = o.req("enable", <bool as crate::json_read::FromJson>::from_json)?;
        let p_manual = o.req("manual", <bool as crate::json_read::FromJson>::from_json)?;
        let p_frequency = o.req("frequency", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            desc_set: p_desc_set,
            field_desc: p_field_desc,
            enable: p_enable,
            manual: p_manual,
            frequency: p_frequency,
        })
    }
}

impl LowpassFilterResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for LowpassFilterResponse {
    const DESCRIPTOR: u8 = 0xD4;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "lowpass_filter_response";
}

/// Poll IMU data. Poll one IMU data packet (set 0x80) with the stored or the given format.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PollImuData {
    /// Whether to send the ACK/NACK.
    pub option: crate::types::Gx5PollOption,
    /// Number of descriptors; 0 uses the stored message format.
    pub num_descriptors: u8,
    /// Descriptors to poll, in output order.
    pub descriptors: crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83>,
}

impl Default for PollImuData {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PollImuData {
    const ZERO: Self = Self {
        option: <crate::types::Gx5PollOption as crate::wire::Wire>::ZERO,
        num_descriptors: <u8 as crate::wire::Wire>::ZERO,
        descriptors: <crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_option = <crate::types::Gx5PollOption as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("option"))?;
        let p_num_descriptors =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_descriptors"))?;
        let p_descriptors =
            crate::bounded::BoundedVec::<crate::types::Gx5PollDescriptor, 83>::decode_counted(
                r,
                u64::from(p_num_descriptors),
            )
            .map_err(|e| e.at("descriptors"))?;
        Ok(Self {
            option: p_option,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.option;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("option"))?;
        let v = &self.num_descriptors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_descriptors"))?;
        let v = &self.descriptors;
        v.encode_counted(w, u64::from(self.num_descriptors))
            .map_err(|e| e.at("descriptors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.option;
        crate::json::key(w, &mut first, "option")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.num_descriptors;
        crate::json::key(w, &mut first, "num_descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.descriptors;
        crate::json::key(w, &mut first, "descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PollImuData {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["option", "num_descriptors", "descriptors"])?;
        let p_option = o.req(
            "option",
            <crate::types::Gx5PollOption as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_descriptors = o.req(
            "num_descriptors",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_descriptors = o.req("descriptors", <crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            option: p_option,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }
}

impl PollImuData {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for PollImuData {
    const DESCRIPTOR: u8 = 0x01;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "poll_imu_data";
}

/// Poll GNSS data. Poll one GNSS data packet (set 0x81) with the stored or the given format.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PollGnssData {
    /// Whether to send the ACK/NACK.
    pub option: crate::types::Gx5PollOption,
    /// Number of descriptors; 0 uses the stored message format.
    pub num_descriptors: u8,
    /// Descriptors to poll, in output order.
    pub descriptors: crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83>,
}

impl Default for PollGnssData {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PollGnssData {
    const ZERO: Self = Self {
        option: <crate::types::Gx5PollOption as crate::wire::Wire>::ZERO,
        num_descriptors: <u8 as crate::wire::Wire>::ZERO,
        descriptors: <crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_option = <crate::types::Gx5PollOption as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("option"))?;
        let p_num_descriptors =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_descriptors"))?;
        let p_descriptors =
            crate::bounded::BoundedVec::<crate::types::Gx5PollDescriptor, 83>::decode_counted(
                r,
                u64::from(p_num_descriptors),
            )
            .map_err(|e| e.at("descriptors"))?;
        Ok(Self {
            option: p_option,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.option;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("option"))?;
        let v = &self.num_descriptors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_descriptors"))?;
        let v = &self.descriptors;
        v.encode_counted(w, u64::from(self.num_descriptors))
            .map_err(|e| e.at("descriptors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.option;
        crate::json::key(w, &mut first, "option")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.num_descriptors;
        crate::json::key(w, &mut first, "num_descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.descriptors;
        crate::json::key(w, &mut first, "descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PollGnssData {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["option", "num_descriptors", "descriptors"])?;
        let p_option = o.req(
            "option",
            <crate::types::Gx5PollOption as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_descriptors = o.req(
            "num_descriptors",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_descriptors = o.req("descriptors", <crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            option: p_option,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }
}

impl PollGnssData {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for PollGnssData {
    const DESCRIPTOR: u8 = 0x02;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "poll_gnss_data";
}

/// Poll estimation filter data. Poll one estimation filter data packet (set 0x82) with the stored or the given format.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PollFilterData {
    /// Whether to send the ACK/NACK.
    pub option: crate::types::Gx5PollOption,
    /// Number of descriptors; 0 uses the stored message format.
    pub num_descriptors: u8,
    /// Descriptors to poll, in output order.
    pub descriptors: crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83>,
}

impl Default for PollFilterData {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PollFilterData {
    const ZERO: Self = Self {
        option: <crate::types::Gx5PollOption as crate::wire::Wire>::ZERO,
        num_descriptors: <u8 as crate::wire::Wire>::ZERO,
        descriptors: <crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_option = <crate::types::Gx5PollOption as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("option"))?;
        let p_num_descriptors =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_descriptors"))?;
        let p_descriptors =
            crate::bounded::BoundedVec::<crate::types::Gx5PollDescriptor, 83>::decode_counted(
                r,
                u64::from(p_num_descriptors),
            )
            .map_err(|e| e.at("descriptors"))?;
        Ok(Self {
            option: p_option,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.option;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("option"))?;
        let v = &self.num_descriptors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_descriptors"))?;
        let v = &self.descriptors;
        v.encode_counted(w, u64::from(self.num_descriptors))
            .map_err(|e| e.at("descriptors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.option;
        crate::json::key(w, &mut first, "option")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.num_descriptors;
        crate::json::key(w, &mut first, "num_descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.descriptors;
        crate::json::key(w, &mut first, "descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PollFilterData {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["option", "num_descriptors", "descriptors"])?;
        let p_option = o.req(
            "option",
            <crate::types::Gx5PollOption as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_descriptors = o.req(
            "num_descriptors",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_descriptors = o.req("descriptors", <crate::bounded::BoundedVec<crate::types::Gx5PollDescriptor, 83> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            option: p_option,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }
}

impl PollFilterData {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for PollFilterData {
    const DESCRIPTOR: u8 = 0x03;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "poll_filter_data";
}

/// Poll NMEA data. Poll NMEA sentences once, with the given format or (if none is given) the stored NMEA message format. The sentences are sent separately as plain NMEA.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PollNmeaData {
    /// Do not send the ACK/NACK reply.
    pub suppress_ack: bool,
    /// Number of format entries.
    pub count: u8,
    /// Sentences to produce.
    pub format_entries: crate::bounded::BoundedVec<crate::types::NmeaMessage, 50>,
}

impl Default for PollNmeaData {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PollNmeaData {
    const ZERO: Self = Self {
        suppress_ack: <bool as crate::wire::Wire>::ZERO,
        count: <u8 as crate::wire::Wire>::ZERO,
        format_entries:
            <crate::bounded::BoundedVec<crate::types::NmeaMessage, 50> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_suppress_ack =
            <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("suppress_ack"))?;
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        let p_format_entries =
            crate::bounded::BoundedVec::<crate::types::NmeaMessage, 50>::decode_counted(
                r,
                u64::from(p_count),
            )
            .map_err(|e| e.at("format_entries"))?;
        Ok(Self {
            suppress_ack: p_suppress_ack,
            count: p_count,
            format_entries: p_format_entries,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.suppress_ack;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("suppress_ack"))?;
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        let v = &self.format_entries;
        v.encode_counted(w, u64::from(self.count))
            .map_err(|e| e.at("format_entries"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.suppress_ack;
        crate::json::key(w, &mut first, "suppress_ack")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.format_entries;
        crate::json::key(w, &mut first, "format_entries")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PollNmeaData {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["suppress_ack", "count", "format_entries"])?;
        let p_suppress_ack = o.req(
            "suppress_ack",
            <bool as crate::json_read::FromJson>::from_json,
        )?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_format_entries = o.req("format_entries", <crate::bounded::BoundedVec<crate::types::NmeaMessage, 50> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            suppress_ack: p_suppress_ack,
            count: p_count,
            format_entries: p_format_entries,
        })
    }
}

impl PollNmeaData {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for PollNmeaData {
    const DESCRIPTOR: u8 = 0x04;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "poll_nmea_data";
}

/// Poll data. Poll one data packet of the given descriptor set, with the listed descriptors (in that order) or, if none, the stored message format. The data comes as a separate data packet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PollData {
    /// Data descriptor set to poll.
    pub desc_set: u8,
    /// Do not send the ACK/NACK reply.
    pub suppress_ack: bool,
    /// Number of descriptors.
    pub num_descriptors: u8,
    /// Field descriptors, in output order.
    pub descriptors: crate::bounded::BoundedVec<u8, 250>,
}

impl Default for PollData {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PollData {
    const ZERO: Self = Self {
        desc_set: <u8 as crate::wire::Wire>::ZERO,
        suppress_ack: <bool as crate::wire::Wire>::ZERO,
        num_descriptors: <u8 as crate::wire::Wire>::ZERO,
        descriptors: <crate::bounded::BoundedVec<u8, 250> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_desc_set = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("desc_set"))?;
        let p_suppress_ack =
            <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("suppress_ack"))?;
        let p_num_descriptors =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_descriptors"))?;
        let p_descriptors =
            crate::bounded::BoundedVec::<u8, 250>::decode_counted(r, u64::from(p_num_descriptors))
                .map_err(|e| e.at("descriptors"))?;
        Ok(Self {
            desc_set: p_desc_set,
            suppress_ack: p_suppress_ack,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.desc_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("desc_set"))?;
        let v = &self.suppress_ack;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("suppress_ack"))?;
        let v = &self.num_descriptors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_descriptors"))?;
        let v = &self.descriptors;
        v.encode_counted(w, u64::from(self.num_descriptors))
            .map_err(|e| e.at("descriptors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.desc_set;
        crate::json::key(w, &mut first, "desc_set")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.suppress_ack;
        crate::json::key(w, &mut first, "suppress_ack")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.num_descriptors;
        crate::json::key(w, &mut first, "num_descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.descriptors;
        crate::json::key(w, &mut first, "descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PollData {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["desc_set", "suppress_ack", "num_descriptors", "descriptors"],
        )?;
        let p_desc_set = o.req("desc_set", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_suppress_ack = o.req(
            "suppress_ack",
            <bool as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_descriptors = o.req(
            "num_descriptors",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_descriptors = o.req(
            "descriptors",
            <crate::bounded::BoundedVec<u8, 250> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            desc_set: p_desc_set,
            suppress_ack: p_suppress_ack,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }
}

impl PollData {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for PollData {
    const DESCRIPTOR: u8 = 0x0D;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "poll_data";
}

/// Get IMU data base rate. Get the IMU data base rate, from which message format decimations are computed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetImuBaseRate {}

impl Default for GetImuBaseRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetImuBaseRate {
    const ZERO: Self = Self {};
    const FIXED_SIZE: Option<usize> = Some(0);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let _ = r;
        Ok(Self {})
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let _ = w;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        w.write_str("{}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GetImuBaseRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl GetImuBaseRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GetImuBaseRate {
    const DESCRIPTOR: u8 = 0x06;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "get_imu_base_rate";
}

/// IMU data base rate. IMU data base rate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImuBaseRate {
    /// Base rate used for rate decimation calculations. Units: Hz.
    pub rate: u16,
}

impl Default for ImuBaseRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ImuBaseRate {
    const ZERO: Self = Self {
        rate: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_rate = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("rate"))?;
        Ok(Self { rate: p_rate })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.rate;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("rate"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.rate;
        crate::json::key(w, &mut first, "rate")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ImuBaseRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["rate"])?;
        let p_rate = o.req("rate", <u16 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { rate: p_rate })
    }
}

impl ImuBaseRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for ImuBaseRate {
    const DESCRIPTOR: u8 = 0x83;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "imu_base_rate";
}

/// Get GNSS data base rate. Get the GNSS data base rate, from which message format decimations are computed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetGnssBaseRate {}

impl Default for GetGnssBaseRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetGnssBaseRate {
    const ZERO: Self = Self {};
    const FIXED_SIZE: Option<usize> = Some(0);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let _ = r;
        Ok(Self {})
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let _ = w;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        w.write_str("{}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GetGnssBaseRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl GetGnssBaseRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GetGnssBaseRate {
    const DESCRIPTOR: u8 = 0x07;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "get_gnss_base_rate";
}

/// GNSS data base rate. GNSS data base rate (4 Hz on the 3DM-GX5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssBaseRate {
    /// Base rate used for rate decimation calculations. Units: Hz.
    pub rate: u16,
}

impl Default for GnssBaseRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssBaseRate {
    const ZERO: Self = Self {
        rate: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_rate = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("rate"))?;
        Ok(Self { rate: p_rate })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.rate;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("rate"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.rate;
        crate::json::key(w, &mut first, "rate")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssBaseRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["rate"])?;
        let p_rate = o.req("rate", <u16 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { rate: p_rate })
    }
}

impl GnssBaseRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GnssBaseRate {
    const DESCRIPTOR: u8 = 0x84;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gnss_base_rate";
}

/// Get estimation filter data base rate. Get the estimation filter data base rate, from which message format decimations are computed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetFilterBaseRate {}

impl Default for GetFilterBaseRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetFilterBaseRate {
    const ZERO: Self = Self {};
    const FIXED_SIZE: Option<usize> = Some(0);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let _ = r;
        Ok(Self {})
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let _ = w;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        w.write_str("{}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GetFilterBaseRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        crate::json_read::Obj::new(v, &[])?;
        Ok(Self {})
    }
}

impl GetFilterBaseRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GetFilterBaseRate {
    const DESCRIPTOR: u8 = 0x0B;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "get_filter_base_rate";
}

/// Estimation filter data base rate. Estimation filter data base rate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilterBaseRate {
    /// Base rate used for rate decimation calculations. Units: Hz.
    pub rate: u16,
}

impl Default for FilterBaseRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for FilterBaseRate {
    const ZERO: Self = Self {
        rate: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_rate = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("rate"))?;
        Ok(Self { rate: p_rate })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.rate;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("rate"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.rate;
        crate::json::key(w, &mut first, "rate")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for FilterBaseRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["rate"])?;
        let p_rate = o.req("rate", <u16 as crate::json_read::FromJson>::from_json)?;
        Ok(Self { rate: p_rate })
    }
}

impl FilterBaseRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for FilterBaseRate {
    const DESCRIPTOR: u8 = 0x8A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "filter_base_rate";
}

/// Get data base rate. Get the base rate of a data descriptor set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetBaseRate {
    /// Data descriptor set (must be supported).
    pub desc_set: u8,
}

impl Default for GetBaseRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetBaseRate {
    const ZERO: Self = Self {
        desc_set: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_desc_set = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("desc_set"))?;
        Ok(Self {
            desc_set: p_desc_set,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.desc_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("desc_set"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.desc_set;
        crate::json::key(w, &mut first, "desc_set")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GetBaseRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["desc_set"])?;
        let p_desc_set = o.req("desc_set", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            desc_set: p_desc_set,
        })
    }
}

impl GetBaseRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GetBaseRate {
    const DESCRIPTOR: u8 = 0x0E;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "get_base_rate";
}

/// Data base rate. Base rate of a data descriptor set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BaseRate {
    /// Echo of the descriptor set in the command.
    pub desc_set: u8,
    /// Base rate; 0 means variable or unknown (data sent as it arrives). Units: Hz.
    pub rate: u16,
}

impl Default for BaseRate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for BaseRate {
    const ZERO: Self = Self {
        desc_set: <u8 as crate::wire::Wire>::ZERO,
        rate: <u16 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(3);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_desc_set = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("desc_set"))?;
        let p_rate = <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("rate"))?;
        Ok(Self {
            desc_set: p_desc_set,
            rate: p_rate,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.desc_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("desc_set"))?;
        let v = &self.rate;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("rate"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.desc_set;
        crate::json::key(w, &mut first, "desc_set")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.rate;
        crate::json::key(w, &mut first, "rate")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for BaseRate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["desc_set", "rate"])?;
        let p_desc_set = o.req("desc_set", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_rate = o.req("rate", <u16 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            desc_set: p_desc_set,
            rate: p_rate,
        })
    }
}

impl BaseRate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for BaseRate {
    const DESCRIPTOR: u8 = 0x8E;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "base_rate";
}

/// IMU message format. Set, read, save, load or reset the IMU data (0x80) message format.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImuMessageFormat {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Number of descriptors (0 for every function except write, which may also leave it out). Sent for: write, read, save, load, default.
    pub num_descriptors: Option<u8>,
    /// Descriptors and rate decimations (decimation = base rate / desired rate). Sent for: write, read, save, load, default.
    pub descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
}

impl Default for ImuMessageFormat {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ImuMessageFormat {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        num_descriptors: None,
        descriptors: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_num_descriptors = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_descriptors"))?)
        } else {
            None
        };
        let p_descriptors = if r.left() > 0 {
            Some(
                crate::bounded::BoundedVec::<crate::types::DescriptorRate, 83>::decode_counted(
                    r,
                    p_num_descriptors.map_or(0, u64::from),
                )
                .map_err(|e| e.at("descriptors"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.num_descriptors {
            optionals.present("num_descriptors")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_descriptors"))?;
        } else {
            optionals.absent("num_descriptors");
        }
        if let Some(v) = &self.descriptors {
            optionals.present("descriptors")?;
            v.encode_counted(w, self.num_descriptors.map_or(0, u64::from))
                .map_err(|e| e.at("descriptors"))?;
        } else {
            optionals.absent("descriptors");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.num_descriptors {
            crate::json::key(w, &mut first, "num_descriptors")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.descriptors {
            crate::json::key(w, &mut first, "descriptors")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ImuMessageFormat {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "num_descriptors", "descriptors"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_descriptors = o.opt(
            "num_descriptors",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_descriptors = o.opt("descriptors", <crate::bounded::BoundedVec<crate::types::DescriptorRate, 83> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }
}

impl ImuMessageFormat {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for ImuMessageFormat {
    const DESCRIPTOR: u8 = 0x08;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "imu_message_format";
}

/// Current IMU message format. The IMU data message format.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImuMessageFormatResponse {
    /// Number of descriptors.
    pub num_descriptors: u8,
    /// Descriptors and rate decimations.
    pub descriptors: crate::bounded::BoundedVec<crate::types::DescriptorRate, 84>,
}

impl Default for ImuMessageFormatResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ImuMessageFormatResponse {
    const ZERO: Self = Self {
        num_descriptors: <u8 as crate::wire::Wire>::ZERO,
        descriptors: <crate::bounded::BoundedVec<crate::types::DescriptorRate, 84> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_num_descriptors =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_descriptors"))?;
        let p_descriptors =
            crate::bounded::BoundedVec::<crate::types::DescriptorRate, 84>::decode_counted(
                r,
                u64::from(p_num_descriptors),
            )
            .map_err(|e| e.at("descriptors"))?;
        Ok(Self {
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.num_descriptors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_descriptors"))?;
        let v = &self.descriptors;
        v.encode_counted(w, u64::from(self.num_descriptors))
            .map_err(|e| e.at("descriptors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.num_descriptors;
        crate::json::key(w, &mut first, "num_descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.descriptors;
        crate::json::key(w, &mut first, "descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ImuMessageFormatResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["num_descriptors", "descriptors"])?;
        let p_num_descriptors = o.req(
            "num_descriptors",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_descriptors = o.req("descriptors", <crate::bounded::BoundedVec<crate::types::DescriptorRate, 84> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }
}

impl ImuMessageFormatResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for ImuMessageFormatResponse {
    const DESCRIPTOR: u8 = 0x80;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "imu_message_format_response";
}

/// GNSS message format. Set, read, save, load or reset the GNSS data (0x81) message format.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssMessageFormat {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Number of descriptors (0 for every function except write, which may also leave it out). Sent for: write, read, save, load, default.
    pub num_descriptors: Option<u8>,
    /// Descriptors and rate decimations (decimation = base rate / desired rate). Sent for: write, read, save, load, default.
    pub descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
}

impl Default for GnssMessageFormat {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssMessageFormat {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        num_descriptors: None,
        descriptors: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_num_descriptors = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_descriptors"))?)
        } else {
            None
        };
        let p_descriptors = if r.left() > 0 {
            Some(
                crate::bounded::BoundedVec::<crate::types::DescriptorRate, 83>::decode_counted(
                    r,
                    p_num_descriptors.map_or(0, u64::from),
                )
                .map_err(|e| e.at("descriptors"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.num_descriptors {
            optionals.present("num_descriptors")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_descriptors"))?;
        } else {
            optionals.absent("num_descriptors");
        }
        if let Some(v) = &self.descriptors {
            optionals.present("descriptors")?;
            v.encode_counted(w, self.num_descriptors.map_or(0, u64::from))
                .map_err(|e| e.at("descriptors"))?;
        } else {
            optionals.absent("descriptors");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.num_descriptors {
            crate::json::key(w, &mut first, "num_descriptors")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.descriptors {
            crate::json::key(w, &mut first, "descriptors")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssMessageFormat {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "num_descriptors", "descriptors"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_descriptors = o.opt(
            "num_descriptors",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_descriptors = o.opt("descriptors", <crate::bounded::BoundedVec<crate::types::DescriptorRate, 83> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }
}

impl GnssMessageFormat {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GnssMessageFormat {
    const DESCRIPTOR: u8 = 0x09;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gnss_message_format";
}

/// Current GNSS message format. The GNSS data message format.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssMessageFormatResponse {
    /// Number of descriptors.
    pub num_descriptors: u8,
    /// Descriptors and rate decimations.
    pub descriptors: crate::bounded::BoundedVec<crate::types::DescriptorRate, 84>,
}

impl Default for GnssMessageFormatResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssMessageFormatResponse {
    const ZERO: Self = Self {
        num_descriptors: <u8 as crate::wire::Wire>::ZERO,
        descriptors: <crate::bounded::BoundedVec<crate::types::DescriptorRate, 84> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_num_descriptors =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_descriptors"))?;
        let p_descriptors =
            crate::bounded::BoundedVec::<crate::types::DescriptorRate, 84>::decode_counted(
                r,
                u64::from(p_num_descriptors),
            )
            .map_err(|e| e.at("descriptors"))?;
        Ok(Self {
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.num_descriptors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_descriptors"))?;
        let v = &self.descriptors;
        v.encode_counted(w, u64::from(self.num_descriptors))
            .map_err(|e| e.at("descriptors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.num_descriptors;
        crate::json::key(w, &mut first, "num_descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.descriptors;
        crate::json::key(w, &mut first, "descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssMessageFormatResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["num_descriptors", "descriptors"])?;
        let p_num_descriptors = o.req(
            "num_descriptors",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_descriptors = o.req("descriptors", <crate::bounded::BoundedVec<crate::types::DescriptorRate, 84> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }
}

impl GnssMessageFormatResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GnssMessageFormatResponse {
    const DESCRIPTOR: u8 = 0x81;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gnss_message_format_response";
}

/// Estimation filter message format. Set, read, save, load or reset the estimation filter data (0x82) message format.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilterMessageFormat {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Number of descriptors (0 for every function except write, which may also leave it out). Sent for: write, read, save, load, default.
    pub num_descriptors: Option<u8>,
    /// Descriptors and rate decimations (decimation = base rate / desired rate). Sent for: write, read, save, load, default.
    pub descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
}

impl Default for FilterMessageFormat {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for FilterMessageFormat {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        num_descriptors: None,
        descriptors: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_num_descriptors = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_descriptors"))?)
        } else {
            None
        };
        let p_descriptors = if r.left() > 0 {
            Some(
                crate::bounded::BoundedVec::<crate::types::DescriptorRate, 83>::decode_counted(
                    r,
                    p_num_descriptors.map_or(0, u64::from),
                )
                .map_err(|e| e.at("descriptors"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.num_descriptors {
            optionals.present("num_descriptors")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_descriptors"))?;
        } else {
            optionals.absent("num_descriptors");
        }
        if let Some(v) = &self.descriptors {
            optionals.present("descriptors")?;
            v.encode_counted(w, self.num_descriptors.map_or(0, u64::from))
                .map_err(|e| e.at("descriptors"))?;
        } else {
            optionals.absent("descriptors");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.num_descriptors {
            crate::json::key(w, &mut first, "num_descriptors")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.descriptors {
            crate::json::key(w, &mut first, "descriptors")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for FilterMessageFormat {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "num_descriptors", "descriptors"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_descriptors = o.opt(
            "num_descriptors",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_descriptors = o.opt("descriptors", <crate::bounded::BoundedVec<crate::types::DescriptorRate, 83> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }
}

impl FilterMessageFormat {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for FilterMessageFormat {
    const DESCRIPTOR: u8 = 0x0A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "filter_message_format";
}

/// Current estimation filter message format. The estimation filter data message format.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilterMessageFormatResponse {
    /// Number of descriptors.
    pub num_descriptors: u8,
    /// Descriptors and rate decimations.
    pub descriptors: crate::bounded::BoundedVec<crate::types::DescriptorRate, 84>,
}

impl Default for FilterMessageFormatResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for FilterMessageFormatResponse {
    const ZERO: Self = Self {
        num_descriptors: <u8 as crate::wire::Wire>::ZERO,
        descriptors: <crate::bounded::BoundedVec<crate::types::DescriptorRate, 84> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_num_descriptors =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_descriptors"))?;
        let p_descriptors =
            crate::bounded::BoundedVec::<crate::types::DescriptorRate, 84>::decode_counted(
                r,
                u64::from(p_num_descriptors),
            )
            .map_err(|e| e.at("descriptors"))?;
        Ok(Self {
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.num_descriptors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_descriptors"))?;
        let v = &self.descriptors;
        v.encode_counted(w, u64::from(self.num_descriptors))
            .map_err(|e| e.at("descriptors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.num_descriptors;
        crate::json::key(w, &mut first, "num_descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.descriptors;
        crate::json::key(w, &mut first, "descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for FilterMessageFormatResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["num_descriptors", "descriptors"])?;
        let p_num_descriptors = o.req(
            "num_descriptors",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_descriptors = o.req("descriptors", <crate::bounded::BoundedVec<crate::types::DescriptorRate, 84> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }
}

impl FilterMessageFormatResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for FilterMessageFormatResponse {
    const DESCRIPTOR: u8 = 0x82;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "filter_message_format_response";
}

/// NMEA message format. Set, read, save, load or reset the list of NMEA sentences the device outputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NmeaMessageFormat {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Number of format entries. Sent for: write.
    pub count: Option<u8>,
    /// Sentences, talkers, sources and decimations. Sent for: write.
    pub format_entries: Option<crate::bounded::BoundedVec<crate::types::NmeaMessage, 50>>,
}

impl Default for NmeaMessageFormat {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for NmeaMessageFormat {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        count: None,
        format_entries: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_count = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?)
        } else {
            None
        };
        let p_format_entries = if r.left() > 0 {
            Some(
                crate::bounded::BoundedVec::<crate::types::NmeaMessage, 50>::decode_counted(
                    r,
                    p_count.map_or(0, u64::from),
                )
                .map_err(|e| e.at("format_entries"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            count: p_count,
            format_entries: p_format_entries,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.count {
            optionals.present("count")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        } else {
            optionals.absent("count");
        }
        if let Some(v) = &self.format_entries {
            optionals.present("format_entries")?;
            v.encode_counted(w, self.count.map_or(0, u64::from))
                .map_err(|e| e.at("format_entries"))?;
        } else {
            optionals.absent("format_entries");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.count {
            crate::json::key(w, &mut first, "count")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.format_entries {
            crate::json::key(w, &mut first, "format_entries")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for NmeaMessageFormat {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "count", "format_entries"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_count = o.opt("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_format_entries = o.opt("format_entries", <crate::bounded::BoundedVec<crate::types::NmeaMessage, 50> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            count: p_count,
            format_entries: p_format_entries,
        })
    }
}

impl NmeaMessageFormat {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for NmeaMessageFormat {
    const DESCRIPTOR: u8 = 0x0C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "nmea_message_format";
}

/// Current NMEA message format. The NMEA sentence list.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NmeaMessageFormatResponse {
    /// Number of format entries.
    pub count: u8,
    /// Sentences, talkers, sources and decimations.
    pub format_entries: crate::bounded::BoundedVec<crate::types::NmeaMessage, 50>,
}

impl Default for NmeaMessageFormatResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for NmeaMessageFormatResponse {
    const ZERO: Self = Self {
        count: <u8 as crate::wire::Wire>::ZERO,
        format_entries:
            <crate::bounded::BoundedVec<crate::types::NmeaMessage, 50> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_count = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("count"))?;
        let p_format_entries =
            crate::bounded::BoundedVec::<crate::types::NmeaMessage, 50>::decode_counted(
                r,
                u64::from(p_count),
            )
            .map_err(|e| e.at("format_entries"))?;
        Ok(Self {
            count: p_count,
            format_entries: p_format_entries,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("count"))?;
        let v = &self.format_entries;
        v.encode_counted(w, u64::from(self.count))
            .map_err(|e| e.at("format_entries"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.count;
        crate::json::key(w, &mut first, "count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.format_entries;
        crate::json::key(w, &mut first, "format_entries")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for NmeaMessageFormatResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["count", "format_entries"])?;
        let p_count = o.req("count", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_format_entries = o.req("format_entries", <crate::bounded::BoundedVec<crate::types::NmeaMessage, 50> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            count: p_count,
            format_entries: p_format_entries,
        })
    }
}

impl NmeaMessageFormatResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for NmeaMessageFormatResponse {
    const DESCRIPTOR: u8 = 0x8C;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "nmea_message_format_response";
}

/// Message format. Set, read, save, load or reset the message format of a data descriptor set. Output keeps the order of the list.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MessageFormat {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Data descriptor set; 0 means all sets for save, load and default. Sent for: write, read, save, load, default.
    pub desc_set: u8,
    /// Number of descriptors. Sent for: write.
    pub num_descriptors: Option<u8>,
    /// Descriptors and decimations. Sent for: write.
    pub descriptors: Option<crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>>,
}

impl Default for MessageFormat {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MessageFormat {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        desc_set: <u8 as crate::wire::Wire>::ZERO,
        num_descriptors: None,
        descriptors: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_desc_set = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("desc_set"))?;
        let p_num_descriptors = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_descriptors"))?)
        } else {
            None
        };
        let p_descriptors = if r.left() > 0 {
            Some(
                crate::bounded::BoundedVec::<crate::types::DescriptorRate, 83>::decode_counted(
                    r,
                    p_num_descriptors.map_or(0, u64::from),
                )
                .map_err(|e| e.at("descriptors"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            desc_set: p_desc_set,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.desc_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("desc_set"))?;
        if let Some(v) = &self.num_descriptors {
            optionals.present("num_descriptors")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_descriptors"))?;
        } else {
            optionals.absent("num_descriptors");
        }
        if let Some(v) = &self.descriptors {
            optionals.present("descriptors")?;
            v.encode_counted(w, self.num_descriptors.map_or(0, u64::from))
                .map_err(|e| e.at("descriptors"))?;
        } else {
            optionals.absent("descriptors");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.desc_set;
        crate::json::key(w, &mut first, "desc_set")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.num_descriptors {
            crate::json::key(w, &mut first, "num_descriptors")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.descriptors {
            crate::json::key(w, &mut first, "descriptors")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MessageFormat {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["function", "desc_set", "num_descriptors", "descriptors"],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_desc_set = o.req("desc_set", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_num_descriptors = o.opt(
            "num_descriptors",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_descriptors = o.opt("descriptors", <crate::bounded::BoundedVec<crate::types::DescriptorRate, 83> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            desc_set: p_desc_set,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }
}

impl MessageFormat {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for MessageFormat {
    const DESCRIPTOR: u8 = 0x0F;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "message_format";
}

/// Current message format. The message format of a data descriptor set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MessageFormatResponse {
    /// Echo of the descriptor set in the command.
    pub desc_set: u8,
    /// Number of descriptors.
    pub num_descriptors: u8,
    /// Descriptors and decimations.
    pub descriptors: crate::bounded::BoundedVec<crate::types::DescriptorRate, 83>,
}

impl Default for MessageFormatResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for MessageFormatResponse {
    const ZERO: Self = Self {
        desc_set: <u8 as crate::wire::Wire>::ZERO,
        num_descriptors: <u8 as crate::wire::Wire>::ZERO,
        descriptors: <crate::bounded::BoundedVec<crate::types::DescriptorRate, 83> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_desc_set = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("desc_set"))?;
        let p_num_descriptors =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_descriptors"))?;
        let p_descriptors =
            crate::bounded::BoundedVec::<crate::types::DescriptorRate, 83>::decode_counted(
                r,
                u64::from(p_num_descriptors),
            )
            .map_err(|e| e.at("descriptors"))?;
        Ok(Self {
            desc_set: p_desc_set,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.desc_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("desc_set"))?;
        let v = &self.num_descriptors;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_descriptors"))?;
        let v = &self.descriptors;
        v.encode_counted(w, u64::from(self.num_descriptors))
            .map_err(|e| e.at("descriptors"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.desc_set;
        crate::json::key(w, &mut first, "desc_set")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.num_descriptors;
        crate::json::key(w, &mut first, "num_descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.descriptors;
        crate::json::key(w, &mut first, "descriptors")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for MessageFormatResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["desc_set", "num_descriptors", "descriptors"])?;
        let p_desc_set = o.req("desc_set", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_num_descriptors = o.req(
            "num_descriptors",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_descriptors = o.req("descriptors", <crate::bounded::BoundedVec<crate::types::DescriptorRate, 83> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            desc_set: p_desc_set,
            num_descriptors: p_num_descriptors,
            descriptors: p_descriptors,
        })
    }
}

impl MessageFormatResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for MessageFormatResponse {
    const DESCRIPTOR: u8 = 0x8F;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "message_format_response";
}

/// Factory streaming. Configure every data stream with the predefined formats technical support asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FactoryStreaming {
    /// How to combine the support descriptors with the current formats.
    pub action: crate::types::FactoryStreamingAction,
    /// Reserved; set to 0x00.
    pub reserved: u8,
}

impl Default for FactoryStreaming {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for FactoryStreaming {
    const ZERO: Self = Self {
        action: <crate::types::FactoryStreamingAction as crate::wire::Wire>::ZERO,
        reserved: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_action = <crate::types::FactoryStreamingAction as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("action"))?;
        let p_reserved = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("reserved"))?;
        Ok(Self {
            action: p_action,
            reserved: p_reserved,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.action;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("action"))?;
        let v = &self.reserved;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("reserved"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.action;
        crate::json::key(w, &mut first, "action")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.reserved;
        crate::json::key(w, &mut first, "reserved")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for FactoryStreaming {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["action", "reserved"])?;
        let p_action = o.req(
            "action",
            <crate::types::FactoryStreamingAction as crate::json_read::FromJson>::from_json,
        )?;
        let p_reserved = o.req("reserved", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            action: p_action,
            reserved: p_reserved,
        })
    }
}

impl FactoryStreaming {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for FactoryStreaming {
    const DESCRIPTOR: u8 = 0x10;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "factory_streaming";
}

/// Data stream control. Layout for device gx5_45.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DataStreamControlGx5_45 {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Stream to control. Sent for: write, read, save, load, default.
    pub device_selector: crate::types::Gx5StreamSelector,
    /// 0x00 disable, 0x01 enable (default); ignored except for write, and may be left out by the other functions. Sent for: write, read, save, load, default.
    pub enable: Option<u8>,
}

impl Default for DataStreamControlGx5_45 {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DataStreamControlGx5_45 {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        device_selector: <crate::types::Gx5StreamSelector as crate::wire::Wire>::ZERO,
        enable: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_device_selector = <crate::types::Gx5StreamSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("device_selector"))?;
        let p_enable = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            device_selector: p_device_selector,
            enable: p_enable,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.device_selector;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("device_selector"))?;
        if let Some(v) = &self.enable {
            optionals.present("enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        } else {
            optionals.absent("enable");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.device_selector;
        crate::json::key(w, &mut first, "device_selector")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.enable {
            crate::json::key(w, &mut first, "enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DataStreamControlGx5_45 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "device_selector", "enable"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_device_selector = o.req(
            "device_selector",
            <crate::types::Gx5StreamSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable = o.opt("enable", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            device_selector: p_device_selector,
            enable: p_enable,
        })
    }
}

impl DataStreamControlGx5_45 {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for DataStreamControlGx5_45 {
    const DESCRIPTOR: u8 = 0x11;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "data_stream_control";
}

/// Data stream control. Layout for device cv7_ins.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DataStreamControlCv7Ins {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Data descriptor set of the stream; 0 means all streams for save, load and default. Sent for: write, read, save, load, default.
    pub desc_set: u8,
    /// Enable (true) or disable (false) the stream. Sent for: write.
    pub enable: Option<bool>,
}

impl Default for DataStreamControlCv7Ins {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DataStreamControlCv7Ins {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        desc_set: <u8 as crate::wire::Wire>::ZERO,
        enable: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_desc_set = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("desc_set"))?;
        let p_enable = if r.left() > 0 {
            Some(<bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            desc_set: p_desc_set,
            enable: p_enable,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        let v = &self.desc_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("desc_set"))?;
        if let Some(v) = &self.enable {
            optionals.present("enable")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable"))?;
        } else {
            optionals.absent("enable");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.desc_set;
        crate::json::key(w, &mut first, "desc_set")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.enable {
            crate::json::key(w, &mut first, "enable")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DataStreamControlCv7Ins {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "desc_set", "enable"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_desc_set = o.req("desc_set", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_enable = o.opt("enable", <bool as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            desc_set: p_desc_set,
            enable: p_enable,
        })
    }
}

impl DataStreamControlCv7Ins {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for DataStreamControlCv7Ins {
    const DESCRIPTOR: u8 = 0x11;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "data_stream_control";
}

/// Data stream control. Enable or disable continuous output of a data stream. All streams are enabled by default. The enable value is used only by write.
///
/// The layout differs per device; one variant per device, in spec order.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DataStreamControl {
    /// Layout for device `gx5_45`.
    Gx5_45(DataStreamControlGx5_45),
    /// Layout for device `cv7_ins`.
    Cv7Ins(DataStreamControlCv7Ins),
}

impl DataStreamControl {
    /// Field descriptor.
    pub const DESCRIPTOR: u8 = 0x11;
    /// Field name as printed in JSON.
    pub const NAME: &'static str = "data_stream_control";

    /// Device whose layout this value uses.
    pub fn device(&self) -> crate::Device {
        match self {
            Self::Gx5_45(_) => crate::Device::Gx5_45,
            Self::Cv7Ins(_) => crate::Device::Cv7Ins,
        }
    }

    /// Decodes with `device`'s layout if it has one, else tries the layouts in spec order and
    /// keeps the first that decodes (reporting the first layout's error if none does).
    pub fn decode_data(
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Result<Self, crate::error::DecodeError> {
        if device == Some(crate::Device::Gx5_45) {
            return <DataStreamControlGx5_45 as crate::wire::Layout>::decode_data(data)
                .map(Self::Gx5_45);
        }
        if device == Some(crate::Device::Cv7Ins) {
            return <DataStreamControlCv7Ins as crate::wire::Layout>::decode_data(data)
                .map(Self::Cv7Ins);
        }
        let first = match <DataStreamControlGx5_45 as crate::wire::Layout>::decode_data(data) {
            Ok(v) => return Ok(Self::Gx5_45(v)),
            Err(e) => e,
        };
        if let Ok(v) = <DataStreamControlCv7Ins as crate::wire::Layout>::decode_data(data) {
            return Ok(Self::Cv7Ins(v));
        }
        Err(first)
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Gx5_45(v) => crate::wire::Layout::encode_data(v, w),
            Self::Cv7Ins(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Gx5_45(v) => crate::wire::Wire::write_json(v, w),
            Self::Cv7Ins(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the values of `device`'s layout.
    #[cfg(feature = "std")]
    pub fn from_json(
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        match device {
            Some(crate::Device::Gx5_45) => <DataStreamControlGx5_45 as crate::json_read::FromJson>::from_json(values)
                .map(Self::Gx5_45)
                .map_err(|e| e.at("values")),
            Some(crate::Device::Cv7Ins) => <DataStreamControlCv7Ins as crate::json_read::FromJson>::from_json(values)
                .map(Self::Cv7Ins)
                .map_err(|e| e.at("values")),
            None => Err(crate::json_read::JsonError::new(
                "field data_stream_control has per-device layouts; name one with \"device\" (gx5_45, cv7_ins)",
            )
            .at("device")),
        }
    }
}

/// Data stream control (response). Layout for device gx5_45.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DataStreamControlResponseGx5_45 {
    /// Stream.
    pub device_selector: crate::types::Gx5StreamSelector,
    /// Current enable flag: 0x00 disabled, 0x01 enabled.
    pub enabled: u8,
}

impl Default for DataStreamControlResponseGx5_45 {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DataStreamControlResponseGx5_45 {
    const ZERO: Self = Self {
        device_selector: <crate::types::Gx5StreamSelector as crate::wire::Wire>::ZERO,
        enabled: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_device_selector = <crate::types::Gx5StreamSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("device_selector"))?;
        let p_enabled = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enabled"))?;
        Ok(Self {
            device_selector: p_device_selector,
            enabled: p_enabled,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.device_selector;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("device_selector"))?;
        let v = &self.enabled;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enabled"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.device_selector;
        crate::json::key(w, &mut first, "device_selector")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.enabled;
        crate::json::key(w, &mut first, "enabled")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DataStreamControlResponseGx5_45 {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["device_selector", "enabled"])?;
        let p_device_selector = o.req(
            "device_selector",
            <crate::types::Gx5StreamSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_enabled = o.req("enabled", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            device_selector: p_device_selector,
            enabled: p_enabled,
        })
    }
}

impl DataStreamControlResponseGx5_45 {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for DataStreamControlResponseGx5_45 {
    const DESCRIPTOR: u8 = 0x85;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "data_stream_control_response";
}

/// Data stream control (response). Layout for device cv7_ins.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DataStreamControlResponseCv7Ins {
    /// Data descriptor set of the stream.
    pub desc_set: u8,
    /// Whether the stream is enabled.
    pub enabled: bool,
}

impl Default for DataStreamControlResponseCv7Ins {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DataStreamControlResponseCv7Ins {
    const ZERO: Self = Self {
        desc_set: <u8 as crate::wire::Wire>::ZERO,
        enabled: <bool as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_desc_set = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("desc_set"))?;
        let p_enabled = <bool as crate::wire::Wire>::decode(r).map_err(|e| e.at("enabled"))?;
        Ok(Self {
            desc_set: p_desc_set,
            enabled: p_enabled,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.desc_set;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("desc_set"))?;
        let v = &self.enabled;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enabled"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.desc_set;
        crate::json::key(w, &mut first, "desc_set")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.enabled;
        crate::json::key(w, &mut first, "enabled")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DataStreamControlResponseCv7Ins {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["desc_set", "enabled"])?;
        let p_desc_set = o.req("desc_set", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_enabled = o.req("enabled", <bool as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            desc_set: p_desc_set,
            enabled: p_enabled,
        })
    }
}

impl DataStreamControlResponseCv7Ins {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for DataStreamControlResponseCv7Ins {
    const DESCRIPTOR: u8 = 0x85;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "data_stream_control_response";
}

/// Data stream control (response). Whether a data stream is enabled.
///
/// The layout differs per device; one variant per device, in spec order.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DataStreamControlResponse {
    /// Layout for device `gx5_45`.
    Gx5_45(DataStreamControlResponseGx5_45),
    /// Layout for device `cv7_ins`.
    Cv7Ins(DataStreamControlResponseCv7Ins),
}

impl DataStreamControlResponse {
    /// Field descriptor.
    pub const DESCRIPTOR: u8 = 0x85;
    /// Field name as printed in JSON.
    pub const NAME: &'static str = "data_stream_control_response";

    /// Device whose layout this value uses.
    pub fn device(&self) -> crate::Device {
        match self {
            Self::Gx5_45(_) => crate::Device::Gx5_45,
            Self::Cv7Ins(_) => crate::Device::Cv7Ins,
        }
    }

    /// Decodes with `device`'s layout if it has one, else tries the layouts in spec order and
    /// keeps the first that decodes (reporting the first layout's error if none does).
    pub fn decode_data(
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Result<Self, crate::error::DecodeError> {
        if device == Some(crate::Device::Gx5_45) {
            return <DataStreamControlResponseGx5_45 as crate::wire::Layout>::decode_data(data)
                .map(Self::Gx5_45);
        }
        if device == Some(crate::Device::Cv7Ins) {
            return <DataStreamControlResponseCv7Ins as crate::wire::Layout>::decode_data(data)
                .map(Self::Cv7Ins);
        }
        let first =
            match <DataStreamControlResponseGx5_45 as crate::wire::Layout>::decode_data(data) {
                Ok(v) => return Ok(Self::Gx5_45(v)),
                Err(e) => e,
            };
        if let Ok(v) = <DataStreamControlResponseCv7Ins as crate::wire::Layout>::decode_data(data) {
            return Ok(Self::Cv7Ins(v));
        }
        Err(first)
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::Gx5_45(v) => crate::wire::Layout::encode_data(v, w),
            Self::Cv7Ins(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values.
    pub fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::Gx5_45(v) => crate::wire::Wire::write_json(v, w),
            Self::Cv7Ins(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Reads the values of `device`'s layout.
    #[cfg(feature = "std")]
    pub fn from_json(
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Result<Self, crate::json_read::JsonError> {
        match device {
            Some(crate::Device::Gx5_45) => <DataStreamControlResponseGx5_45 as crate::json_read::FromJson>::from_json(values)
                .map(Self::Gx5_45)
                .map_err(|e| e.at("values")),
            Some(crate::Device::Cv7Ins) => <DataStreamControlResponseCv7Ins as crate::json_read::FromJson>::from_json(values)
                .map(Self::Cv7Ins)
                .map_err(|e| e.at("values")),
            None => Err(crate::json_read::JsonError::new(
                "field data_stream_control_response has per-device layouts; name one with \"device\" (gx5_45, cv7_ins)",
            )
            .at("device")),
        }
    }
}

/// Raw RTCM 2.3 message. Send raw RTCM 2.3 differential corrections to the GNSS receiver (message types 1, 2, 3 and 9; no RTK). A stream may be split into chunks of at most 253 bytes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RawRtcmMessage {
    /// Raw RTCM 2.3 bytes, passed through unchanged.
    pub data: crate::bounded::BoundedVec<u8, 253>,
}

impl Default for RawRtcmMessage {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for RawRtcmMessage {
    const ZERO: Self = Self {
        data: <crate::bounded::BoundedVec<u8, 253> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_data =
            crate::bounded::BoundedVec::<u8, 253>::decode_remaining(r).map_err(|e| e.at("data"))?;
        Ok(Self { data: p_data })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.data;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("data"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.data;
        crate::json::key(w, &mut first, "data")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for RawRtcmMessage {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["data"])?;
        let p_data = o.req(
            "data",
            <crate::bounded::BoundedVec<u8, 253> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { data: p_data })
    }
}

impl RawRtcmMessage {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for RawRtcmMessage {
    const DESCRIPTOR: u8 = 0x20;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "raw_rtcm_message";
}

/// GNSS constellation settings. Choose which satellite constellations the receiver tracks and how many tracking channels each may reserve and use (32 channels in all; GLONASS and BeiDou not together).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssConstellationSettings {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Maximum tracking channels to use in total (0 up to the available channels). Sent for: write, read, save, load, default.
    pub max_channels: Option<u16>,
    /// Number of constellation entries. Sent for: write, read, save, load, default.
    pub config_count: Option<u8>,
    /// Per-constellation settings. Sent for: write, read, save, load, default.
    pub settings: Option<crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41>>,
}

impl Default for GnssConstellationSettings {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssConstellationSettings {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        max_channels: None,
        config_count: None,
        settings: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_max_channels = if r.left() > 0 {
            Some(<u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("max_channels"))?)
        } else {
            None
        };
        let p_config_count = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("config_count"))?)
        } else {
            None
        };
        let p_settings = if r.left() > 0 {
            Some(crate::bounded::BoundedVec::<crate::types::ConstellationSettings, 41>::decode_counted(r, p_config_count.map_or(0, u64::from)).map_err(|e| e.at("settings"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            max_channels: p_max_channels,
            config_count: p_config_count,
            settings: p_settings,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.max_channels {
            optionals.present("max_channels")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("max_channels"))?;
        } else {
            optionals.absent("max_channels");
        }
        if let Some(v) = &self.config_count {
            optionals.present("config_count")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("config_count"))?;
        } else {
            optionals.absent("config_count");
        }
        if let Some(v) = &self.settings {
            optionals.present("settings")?;
            v.encode_counted(w, self.config_count.map_or(0, u64::from))
                .map_err(|e| e.at("settings"))?;
        } else {
            optionals.absent("settings");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.max_channels {
            crate::json::key(w, &mut first, "max_channels")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.config_count {
            crate::json::key(w, &mut first, "config_count")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.settings {
            crate::json::key(w, &mut first, "settings")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssConstellationSettings {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &["function", "max_channels", "config_count", "settings"],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_max_channels = o.opt(
            "max_channels",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_config_count = o.opt(
            "config_count",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_settings = o.opt("settings", <crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            max_channels: p_max_channels,
            config_count: p_config_count,
            settings: p_settings,
        })
    }
}

impl GnssConstellationSettings {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GnssConstellationSettings {
    const DESCRIPTOR: u8 = 0x21;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gnss_constellation_settings";
}

/// GNSS constellation settings (response). Current constellation configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssConstellationSettingsResponse {
    /// Tracking channels the receiver has.
    pub max_channels_available: u16,
    /// Maximum tracking channels to use in total.
    pub max_channels: u16,
    /// Number of constellation entries.
    pub config_count: u8,
    /// Per-constellation settings.
    pub settings: crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41>,
}

impl Default for GnssConstellationSettingsResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssConstellationSettingsResponse {
    const ZERO: Self = Self {
        max_channels_available: <u16 as crate::wire::Wire>::ZERO,
        max_channels: <u16 as crate::wire::Wire>::ZERO,
        config_count: <u8 as crate::wire::Wire>::ZERO,
        settings: <crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_max_channels_available =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("max_channels_available"))?;
        let p_max_channels =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("max_channels"))?;
        let p_config_count =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("config_count"))?;
        let p_settings =
            crate::bounded::BoundedVec::<crate::types::ConstellationSettings, 41>::decode_counted(
                r,
                u64::from(p_config_count),
            )
            .map_err(|e| e.at("settings"))?;
        Ok(Self {
            max_channels_available: p_max_channels_available,
            max_channels: p_max_channels,
            config_count: p_config_count,
            settings: p_settings,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.max_channels_available;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("max_channels_available"))?;
        let v = &self.max_channels;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("max_channels"))?;
        let v = &self.config_count;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("config_count"))?;
        let v = &self.settings;
        v.encode_counted(w, u64::from(self.config_count))
            .map_err(|e| e.at("settings"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.max_channels_available;
        crate::json::key(w, &mut first, "max_channels_available")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.max_channels;
        crate::json::key(w, &mut first, "max_channels")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.config_count;
        crate::json::key(w, &mut first, "config_count")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.settings;
        crate::json::key(w, &mut first, "settings")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssConstellationSettingsResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "max_channels_available",
                "max_channels",
                "config_count",
                "settings",
            ],
        )?;
        let p_max_channels_available = o.req(
            "max_channels_available",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_max_channels = o.req(
            "max_channels",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_config_count = o.req(
            "config_count",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_settings = o.req("settings", <crate::bounded::BoundedVec<crate::types::ConstellationSettings, 41> as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            max_channels_available: p_max_channels_available,
            max_channels: p_max_channels,
            config_count: p_config_count,
            settings: p_settings,
        })
    }
}

impl GnssConstellationSettingsResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GnssConstellationSettingsResponse {
    const DESCRIPTOR: u8 = 0xA0;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gnss_constellation_settings_response";
}

/// GNSS SBAS settings. Configure how SBAS satellites augment the GNSS solution: enable, options, and the SBAS PRNs to search for (none listed = all).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssSbasSettings {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// 0 SBAS disabled, 1 SBAS enabled (default). Sent for: write.
    pub enable_sbas: Option<u8>,
    /// SBAS options. Sent for: write.
    pub sbas_options: Option<crate::types::SbasOptions>,
    /// Number of SBAS PRNs listed; 0 includes all. Sent for: write.
    pub num_included_prns: Option<u8>,
    /// SBAS PRNs to search for. Sent for: write.
    pub included_prns: Option<crate::bounded::BoundedVec<u16, 124>>,
}

impl Default for GnssSbasSettings {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssSbasSettings {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        enable_sbas: None,
        sbas_options: None,
        num_included_prns: None,
        included_prns: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_enable_sbas = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable_sbas"))?)
        } else {
            None
        };
        let p_sbas_options = if r.left() > 0 {
            Some(
                <crate::types::SbasOptions as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("sbas_options"))?,
            )
        } else {
            None
        };
        let p_num_included_prns = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_included_prns"))?)
        } else {
            None
        };
        let p_included_prns = if r.left() > 0 {
            Some(
                crate::bounded::BoundedVec::<u16, 124>::decode_counted(
                    r,
                    p_num_included_prns.map_or(0, u64::from),
                )
                .map_err(|e| e.at("included_prns"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            enable_sbas: p_enable_sbas,
            sbas_options: p_sbas_options,
            num_included_prns: p_num_included_prns,
            included_prns: p_included_prns,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.enable_sbas {
            optionals.present("enable_sbas")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable_sbas"))?;
        } else {
            optionals.absent("enable_sbas");
        }
        if let Some(v) = &self.sbas_options {
            optionals.present("sbas_options")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("sbas_options"))?;
        } else {
            optionals.absent("sbas_options");
        }
        if let Some(v) = &self.num_included_prns {
            optionals.present("num_included_prns")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_included_prns"))?;
        } else {
            optionals.absent("num_included_prns");
        }
        if let Some(v) = &self.included_prns {
            optionals.present("included_prns")?;
            v.encode_counted(w, self.num_included_prns.map_or(0, u64::from))
                .map_err(|e| e.at("included_prns"))?;
        } else {
            optionals.absent("included_prns");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.enable_sbas {
            crate::json::key(w, &mut first, "enable_sbas")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.sbas_options {
            crate::json::key(w, &mut first, "sbas_options")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.num_included_prns {
            crate::json::key(w, &mut first, "num_included_prns")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.included_prns {
            crate::json::key(w, &mut first, "included_prns")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssSbasSettings {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "function",
                "enable_sbas",
                "sbas_options",
                "num_included_prns",
                "included_prns",
            ],
        )?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_enable_sbas = o.opt("enable_sbas", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_sbas_options = o.opt(
            "sbas_options",
            <crate::types::SbasOptions as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_included_prns = o.opt(
            "num_included_prns",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_included_prns = o.opt(
            "included_prns",
            <crate::bounded::BoundedVec<u16, 124> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            enable_sbas: p_enable_sbas,
            sbas_options: p_sbas_options,
            num_included_prns: p_num_included_prns,
            included_prns: p_included_prns,
        })
    }
}

impl GnssSbasSettings {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GnssSbasSettings {
    const DESCRIPTOR: u8 = 0x22;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gnss_sbas_settings";
}

/// GNSS SBAS settings (response). Current SBAS configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssSbasSettingsResponse {
    /// 0 SBAS disabled, 1 SBAS enabled.
    pub enable_sbas: u8,
    /// SBAS options.
    pub sbas_options: crate::types::SbasOptions,
    /// Number of SBAS PRNs listed; 0 means all.
    pub num_included_prns: u8,
    /// SBAS PRNs searched for.
    pub included_prns: crate::bounded::BoundedVec<u16, 124>,
}

impl Default for GnssSbasSettingsResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssSbasSettingsResponse {
    const ZERO: Self = Self {
        enable_sbas: <u8 as crate::wire::Wire>::ZERO,
        sbas_options: <crate::types::SbasOptions as crate::wire::Wire>::ZERO,
        num_included_prns: <u8 as crate::wire::Wire>::ZERO,
        included_prns: <crate::bounded::BoundedVec<u16, 124> as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_enable_sbas =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("enable_sbas"))?;
        let p_sbas_options = <crate::types::SbasOptions as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("sbas_options"))?;
        let p_num_included_prns =
            <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("num_included_prns"))?;
        let p_included_prns = crate::bounded::BoundedVec::<u16, 124>::decode_counted(
            r,
            u64::from(p_num_included_prns),
        )
        .map_err(|e| e.at("included_prns"))?;
        Ok(Self {
            enable_sbas: p_enable_sbas,
            sbas_options: p_sbas_options,
            num_included_prns: p_num_included_prns,
            included_prns: p_included_prns,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.enable_sbas;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("enable_sbas"))?;
        let v = &self.sbas_options;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("sbas_options"))?;
        let v = &self.num_included_prns;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("num_included_prns"))?;
        let v = &self.included_prns;
        v.encode_counted(w, u64::from(self.num_included_prns))
            .map_err(|e| e.at("included_prns"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.enable_sbas;
        crate::json::key(w, &mut first, "enable_sbas")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.sbas_options;
        crate::json::key(w, &mut first, "sbas_options")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.num_included_prns;
        crate::json::key(w, &mut first, "num_included_prns")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.included_prns;
        crate::json::key(w, &mut first, "included_prns")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssSbasSettingsResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(
            v,
            &[
                "enable_sbas",
                "sbas_options",
                "num_included_prns",
                "included_prns",
            ],
        )?;
        let p_enable_sbas = o.req("enable_sbas", <u8 as crate::json_read::FromJson>::from_json)?;
        let p_sbas_options = o.req(
            "sbas_options",
            <crate::types::SbasOptions as crate::json_read::FromJson>::from_json,
        )?;
        let p_num_included_prns = o.req(
            "num_included_prns",
            <u8 as crate::json_read::FromJson>::from_json,
        )?;
        let p_included_prns = o.req(
            "included_prns",
            <crate::bounded::BoundedVec<u16, 124> as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            enable_sbas: p_enable_sbas,
            sbas_options: p_sbas_options,
            num_included_prns: p_num_included_prns,
            included_prns: p_included_prns,
        })
    }
}

impl GnssSbasSettingsResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GnssSbasSettingsResponse {
    const DESCRIPTOR: u8 = 0xA1;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gnss_sbas_settings_response";
}

/// GNSS assisted fix control. Enable or disable assisted GNSS fix, which keeps the last fix in non-volatile memory to shorten the time to first fix. Disabling it erases that memory.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssAssistedFixControl {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// Assisted fix on or off. Sent for: write, read, save, load, default.
    pub option: Option<crate::types::AssistedFixOption>,
    /// No flags defined; set to 0xFF. Sent for: write, read, save, load, default.
    pub flags: Option<u8>,
}

impl Default for GnssAssistedFixControl {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssAssistedFixControl {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        option: None,
        flags: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_option = if r.left() > 0 {
            Some(
                <crate::types::AssistedFixOption as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("option"))?,
            )
        } else {
            None
        };
        let p_flags = if r.left() > 0 {
            Some(<u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("flags"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            option: p_option,
            flags: p_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.option {
            optionals.present("option")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("option"))?;
        } else {
            optionals.absent("option");
        }
        if let Some(v) = &self.flags {
            optionals.present("flags")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("flags"))?;
        } else {
            optionals.absent("flags");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.option {
            crate::json::key(w, &mut first, "option")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.flags {
            crate::json::key(w, &mut first, "flags")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssAssistedFixControl {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "option", "flags"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_option = o.opt(
            "option",
            <crate::types::AssistedFixOption as crate::json_read::FromJson>::from_json,
        )?;
        let p_flags = o.opt("flags", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            option: p_option,
            flags: p_flags,
        })
    }
}

impl GnssAssistedFixControl {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GnssAssistedFixControl {
    const DESCRIPTOR: u8 = 0x23;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gnss_assisted_fix_control";
}

/// GNSS assisted fix control (response). Current assisted fix setting.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssAssistedFixControlResponse {
    /// Assisted fix on or off.
    pub option: crate::types::AssistedFixOption,
    /// Assisted fix flags.
    pub flags: u8,
}

impl Default for GnssAssistedFixControlResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssAssistedFixControlResponse {
    const ZERO: Self = Self {
        option: <crate::types::AssistedFixOption as crate::wire::Wire>::ZERO,
        flags: <u8 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(2);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_option = <crate::types::AssistedFixOption as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("option"))?;
        let p_flags = <u8 as crate::wire::Wire>::decode(r).map_err(|e| e.at("flags"))?;
        Ok(Self {
            option: p_option,
            flags: p_flags,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.option;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("option"))?;
        let v = &self.flags;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("flags"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.option;
        crate::json::key(w, &mut first, "option")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.flags;
        crate::json::key(w, &mut first, "flags")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssAssistedFixControlResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["option", "flags"])?;
        let p_option = o.req(
            "option",
            <crate::types::AssistedFixOption as crate::json_read::FromJson>::from_json,
        )?;
        let p_flags = o.req("flags", <u8 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            option: p_option,
            flags: p_flags,
        })
    }
}

impl GnssAssistedFixControlResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GnssAssistedFixControlResponse {
    const DESCRIPTOR: u8 = 0xA2;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gnss_assisted_fix_control_response";
}

/// GNSS assist time update. Give the receiver the current GPS time right after power-up when assisted fix is enabled, so it can judge whether its saved satellite information is still usable.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssAssistTimeUpdate {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// GPS time of week. Units: s. Sent for: write, read.
    pub tow: Option<f64>,
    /// GPS week number. Sent for: write, read.
    pub week_number: Option<u16>,
    /// Accuracy of the given time. Units: s. Sent for: write, read.
    pub accuracy: Option<f32>,
}

impl Default for GnssAssistTimeUpdate {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssAssistTimeUpdate {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        tow: None,
        week_number: None,
        accuracy: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_tow = if r.left() > 0 {
            Some(<f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tow"))?)
        } else {
            None
        };
        let p_week_number = if r.left() > 0 {
            Some(<u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week_number"))?)
        } else {
            None
        };
        let p_accuracy = if r.left() > 0 {
            Some(<f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("accuracy"))?)
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            tow: p_tow,
            week_number: p_week_number,
            accuracy: p_accuracy,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.tow {
            optionals.present("tow")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("tow"))?;
        } else {
            optionals.absent("tow");
        }
        if let Some(v) = &self.week_number {
            optionals.present("week_number")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("week_number"))?;
        } else {
            optionals.absent("week_number");
        }
        if let Some(v) = &self.accuracy {
            optionals.present("accuracy")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("accuracy"))?;
        } else {
            optionals.absent("accuracy");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.tow {
            crate::json::key(w, &mut first, "tow")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.week_number {
            crate::json::key(w, &mut first, "week_number")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        if let Some(v) = &self.accuracy {
            crate::json::key(w, &mut first, "accuracy")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssAssistTimeUpdate {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "tow", "week_number", "accuracy"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_tow = o.opt("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.opt(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_accuracy = o.opt("accuracy", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            function: p_function,
            tow: p_tow,
            week_number: p_week_number,
            accuracy: p_accuracy,
        })
    }
}

impl GnssAssistTimeUpdate {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GnssAssistTimeUpdate {
    const DESCRIPTOR: u8 = 0x24;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gnss_assist_time_update";
}

/// GNSS assist time update (response). Current assist time values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GnssAssistTimeUpdateResponse {
    /// GPS time of week. Units: s.
    pub tow: f64,
    /// GPS week number.
    pub week_number: u16,
    /// Time accuracy. Units: s.
    pub accuracy: f32,
}

impl Default for GnssAssistTimeUpdateResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GnssAssistTimeUpdateResponse {
    const ZERO: Self = Self {
        tow: <f64 as crate::wire::Wire>::ZERO,
        week_number: <u16 as crate::wire::Wire>::ZERO,
        accuracy: <f32 as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(14);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_tow = <f64 as crate::wire::Wire>::decode(r).map_err(|e| e.at("tow"))?;
        let p_week_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("week_number"))?;
        let p_accuracy = <f32 as crate::wire::Wire>::decode(r).map_err(|e| e.at("accuracy"))?;
        Ok(Self {
            tow: p_tow,
            week_number: p_week_number,
            accuracy: p_accuracy,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.tow;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("tow"))?;
        let v = &self.week_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("week_number"))?;
        let v = &self.accuracy;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("accuracy"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.tow;
        crate::json::key(w, &mut first, "tow")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.week_number;
        crate::json::key(w, &mut first, "week_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.accuracy;
        crate::json::key(w, &mut first, "accuracy")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GnssAssistTimeUpdateResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["tow", "week_number", "accuracy"])?;
        let p_tow = o.req("tow", <f64 as crate::json_read::FromJson>::from_json)?;
        let p_week_number = o.req(
            "week_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_accuracy = o.req("accuracy", <f32 as crate::json_read::FromJson>::from_json)?;
        Ok(Self {
            tow: p_tow,
            week_number: p_week_number,
            accuracy: p_accuracy,
        })
    }
}

impl GnssAssistTimeUpdateResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GnssAssistTimeUpdateResponse {
    const DESCRIPTOR: u8 = 0xA3;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "gnss_assist_time_update_response";
}

/// PPS source control. Choose where the pulse-per-second signal comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PpsSource {
    /// Function selector (sent first).
    pub function: crate::types::FunctionSelector,
    /// PPS source. Sent for: write.
    pub source: Option<crate::types::PpsSource>,
}

impl Default for PpsSource {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PpsSource {
    const ZERO: Self = Self {
        function: <crate::types::FunctionSelector as crate::wire::Wire>::ZERO,
        source: None,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_function = <crate::types::FunctionSelector as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("function"))?;
        let p_source = if r.left() > 0 {
            Some(
                <crate::types::PpsSource as crate::wire::Wire>::decode(r)
                    .map_err(|e| e.at("source"))?,
            )
        } else {
            None
        };
        Ok(Self {
            function: p_function,
            source: p_source,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let mut optionals = crate::wire::Optionals::new();
        let v = &self.function;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("function"))?;
        if let Some(v) = &self.source {
            optionals.present("source")?;
            crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        } else {
            optionals.absent("source");
        }
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.function;
        crate::json::key(w, &mut first, "function")?;
        crate::wire::Wire::write_json(v, w)?;
        if let Some(v) = &self.source {
            crate::json::key(w, &mut first, "source")?;
            crate::wire::Wire::write_json(v, w)?;
        }
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PpsSource {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["function", "source"])?;
        let p_function = o.req(
            "function",
            <crate::types::FunctionSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_source = o.opt(
            "source",
            <crate::types::PpsSource as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            function: p_function,
            source: p_source,
        })
    }
}

impl PpsSource {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for PpsSource {
    const DESCRIPTOR: u8 = 0x28;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "pps_source";
}

/// PPS source (response). Current PPS source.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PpsSourceResponse {
    /// PPS source.
    pub source: crate::types::PpsSource,
}

impl Default for PpsSourceResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for PpsSourceResponse {
    const ZERO: Self = Self {
        source: <crate::types::PpsSource as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_source = <crate::types::PpsSource as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("source"))?;
        Ok(Self { source: p_source })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.source;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("source"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.source;
        crate::json::key(w, &mut first, "source")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for PpsSourceResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["source"])?;
        let p_source = o.req(
            "source",
            <crate::types::PpsSource as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { source: p_source })
    }
}

impl PpsSourceResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for PpsSourceResponse {
    const DESCRIPTOR: u8 = 0xA8;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "pps_source_response";
}

/// Get supported events. List the trigger or action types the device supports and how many slots it has.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GetSupportedEvents {
    /// Trigger types or action types.
    pub query: crate::types::SupportedEventsQuery,
}

impl Default for GetSupportedEvents {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for GetSupportedEvents {
    const ZERO: Self = Self {
        query: <crate::types::SupportedEventsQuery as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(1);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_query = <crate::types::SupportedEventsQuery as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("query"))?;
        Ok(Self { query: p_query })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.query;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("query"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.query;
        crate::json::key(w, &mut first, "query")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for GetSupportedEvents {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["query"])?;
        let p_query = o.req(
            "query",
            <crate::types::SupportedEventsQuery as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self { query: p_query })
    }
}

impl GetSupportedEvents {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for GetSupportedEvents {
    const DESCRIPTOR: u8 = 0x2A;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "get_supported_events";
}

/// Supported events. Number of slots and the supported trigger or action types with their maximum counts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SupportedEvents {
    /// Echo of the query.
    pub query: crate::types::SupportedEventsQuery,
    /// Slots and supported types.
    pub info: crate::types::SupportedEventsInfo,
}

impl Default for SupportedEvents {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for SupportedEvents {
    const ZERO: Self = Self {
        query: <crate::types::SupportedEventsQuery as crate::wire::Wire>::ZERO,
        info: crate::types::SupportedEventsInfo::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_query = <crate::types::SupportedEventsQuery as crate::wire::Wire>::decode(r)
            .map_err(|e| e.at("query"))?;
        let p_info = crate::types::SupportedEventsInfo::decode_selected(r, p_query.0)
            .map_err(|e| e.at("info"))?;
        Ok(Self {
            query: p_query,
            info: p_info,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.query;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("query"))?;
        let v = &self.info;
        v.encode_selected(w, self.query.0)
            .map_err(|e| e.at("info"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.query;
        crate::json::key(w, &mut first, "query")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.info;
        crate::json::key(w, &mut first, "info")?;
        v.write_json(w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for SupportedEvents {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["query", "info"])?;
        let p_query = o.req(
            "query",
            <crate::types::SupportedEventsQuery as crate::json_read::FromJson>::from_json,
        )?;
        let p_info = o.req("info", |v| {
            crate::types::SupportedEventsInfo::from_json_selected(v, p_query.0)
        })?;
        Ok(Self {
            query: p_query,
            info: p_info,
        })
    }
}

impl SupportedEvents {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for SupportedEvents {
    const DESCRIPTOR: u8 = 0xB4;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "supported_events";
}

/// Device status. Get the model-specific status of the device, in the basic or the diagnostic structure. The reply layout is tied to the model number (6251 for the 3DM-GX5-45).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceStatus {
    /// Device model number; 6251 (0x186B) for the 3DM-GX5-45.
    pub model_number: u16,
    /// Which status structure to return.
    pub status_selector: crate::types::DeviceStatusSelector,
}

impl Default for DeviceStatus {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceStatus {
    const ZERO: Self = Self {
        model_number: <u16 as crate::wire::Wire>::ZERO,
        status_selector: <crate::types::DeviceStatusSelector as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(3);

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_model_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("model_number"))?;
        let p_status_selector =
            <crate::types::DeviceStatusSelector as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("status_selector"))?;
        Ok(Self {
            model_number: p_model_number,
            status_selector: p_status_selector,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.model_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("model_number"))?;
        let v = &self.status_selector;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("status_selector"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.model_number;
        crate::json::key(w, &mut first, "model_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.status_selector;
        crate::json::key(w, &mut first, "status_selector")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeviceStatus {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["model_number", "status_selector"])?;
        let p_model_number = o.req(
            "model_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_status_selector = o.req(
            "status_selector",
            <crate::types::DeviceStatusSelector as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            model_number: p_model_number,
            status_selector: p_status_selector,
        })
    }
}

impl DeviceStatus {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for DeviceStatus {
    const DESCRIPTOR: u8 = 0x64;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "device_status";
}

/// Device status (response). Echoes of the model number and selector, then the basic or diagnostic status structure chosen by the echoed selector.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeviceStatusResponse {
    /// Echo of the model number.
    pub model_number: u16,
    /// Echo of the status selector.
    pub status_selector: crate::types::DeviceStatusSelector,
    /// The selected status structure.
    pub status: crate::types::Gx5DeviceStatus,
}

impl Default for DeviceStatusResponse {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for DeviceStatusResponse {
    const ZERO: Self = Self {
        model_number: <u16 as crate::wire::Wire>::ZERO,
        status_selector: <crate::types::DeviceStatusSelector as crate::wire::Wire>::ZERO,
        status: crate::types::Gx5DeviceStatus::ZERO,
    };
    const FIXED_SIZE: Option<usize> = None;

    // Always inlined in optimised builds, so that a fixed layout decodes as straight-line
    // loads; not in debug builds, whose unoptimised frames would grow past a thread's stack.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_model_number =
            <u16 as crate::wire::Wire>::decode(r).map_err(|e| e.at("model_number"))?;
        let p_status_selector =
            <crate::types::DeviceStatusSelector as crate::wire::Wire>::decode(r)
                .map_err(|e| e.at("status_selector"))?;
        let p_status = crate::types::Gx5DeviceStatus::decode_selected(r, p_status_selector.0)
            .map_err(|e| e.at("status"))?;
        Ok(Self {
            model_number: p_model_number,
            status_selector: p_status_selector,
            status: p_status,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.model_number;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("model_number"))?;
        let v = &self.status_selector;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("status_selector"))?;
        let v = &self.status;
        v.encode_selected(w, self.status_selector.0)
            .map_err(|e| e.at("status"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.model_number;
        crate::json::key(w, &mut first, "model_number")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.status_selector;
        crate::json::key(w, &mut first, "status_selector")?;
        crate::wire::Wire::write_json(v, w)?;
        let v = &self.status;
        crate::json::key(w, &mut first, "status")?;
        v.write_json(w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for DeviceStatusResponse {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["model_number", "status_selector", "status"])?;
        let p_model_number = o.req(
            "model_number",
            <u16 as crate::json_read::FromJson>::from_json,
        )?;
        let p_status_selector = o.req(
            "status_selector",
            <crate::types::DeviceStatusSelector as crate::json_read::FromJson>::from_json,
        )?;
        let p_status = o.req("status", |v| {
            crate::types::Gx5DeviceStatus::from_json_selected(v, p_status_selector.0)
        })?;
        Ok(Self {
            model_number: p_model_number,
            status_selector: p_status_selector,
            status: p_status,
        })
    }
}

impl DeviceStatusResponse {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x0C;
}

impl crate::wire::Layout for DeviceStatusResponse {
    const DESCRIPTOR: u8 = 0x90;
    const DESCRIPTOR_SET: Option<u8> = Some(0x0C);
    const NAME: &'static str = "device_status_response";
}

/// A decoded field of set 0x0C (`threedm`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `event_control` (0x2B).
    EventControl(EventControl),
    /// `event_control_response` (0xB5).
    EventControlResponse(EventControlResponse),
    /// `get_event_trigger_status` (0x2C).
    GetEventTriggerStatus(GetEventTriggerStatus),
    /// `event_trigger_status` (0xB6).
    EventTriggerStatus(EventTriggerStatus),
    /// `get_event_action_status` (0x2D).
    GetEventActionStatus(GetEventActionStatus),
    /// `event_action_status` (0xB7).
    EventActionStatus(EventActionStatus),
    /// `event_trigger_config` (0x2E).
    EventTriggerConfig(EventTriggerConfig),
    /// `event_trigger_config_response` (0xB8).
    EventTriggerConfigResponse(EventTriggerConfigResponse),
    /// `event_action_config` (0x2F).
    EventActionConfig(EventActionConfig),
    /// `event_action_config_response` (0xB9).
    EventActionConfigResponse(EventActionConfigResponse),
    /// `device_startup_settings` (0x30).
    DeviceStartupSettings(DeviceStartupSettings),
    /// `sensor_to_vehicle_euler` (0x31).
    SensorToVehicleEuler(SensorToVehicleEuler),
    /// `sensor_to_vehicle_euler_response` (0xB1).
    SensorToVehicleEulerResponse(SensorToVehicleEulerResponse),
    /// `sensor_to_vehicle_quaternion` (0x32).
    SensorToVehicleQuaternion(SensorToVehicleQuaternion),
    /// `sensor_to_vehicle_quaternion_response` (0xB2).
    SensorToVehicleQuaternionResponse(SensorToVehicleQuaternionResponse),
    /// `sensor_to_vehicle_dcm` (0x33).
    SensorToVehicleDcm(SensorToVehicleDcm),
    /// `sensor_to_vehicle_dcm_response` (0xB3).
    SensorToVehicleDcmResponse(SensorToVehicleDcmResponse),
    /// `accel_bias` (0x37).
    AccelBias(AccelBias),
    /// `accel_bias_response` (0x9A).
    AccelBiasResponse(AccelBiasResponse),
    /// `gyro_bias` (0x38).
    GyroBias(GyroBias),
    /// `gyro_bias_response` (0x9B).
    GyroBiasResponse(GyroBiasResponse),
    /// `capture_gyro_bias` (0x39).
    CaptureGyroBias(CaptureGyroBias),
    /// `mag_hard_iron_offset` (0x3A).
    MagHardIronOffset(MagHardIronOffset),
    /// `mag_hard_iron_offset_response` (0x9C).
    MagHardIronOffsetResponse(MagHardIronOffsetResponse),
    /// `mag_soft_iron_matrix` (0x3B).
    MagSoftIronMatrix(MagSoftIronMatrix),
    /// `mag_soft_iron_matrix_response` (0x9D).
    MagSoftIronMatrixResponse(MagSoftIronMatrixResponse),
    /// `coning_sculling_enable` (0x3E).
    ConingScullingEnable(ConingScullingEnable),
    /// `coning_sculling_enable_response` (0x9E).
    ConingScullingEnableResponse(ConingScullingEnableResponse),
    /// `uart_baudrate` (0x40).
    UartBaudrate(UartBaudrate),
    /// `uart_baudrate_response` (0x87).
    UartBaudrateResponse(UartBaudrateResponse),
    /// `gpio_config` (0x41).
    GpioConfig(GpioConfig),
    /// `gpio_config_response` (0xC1).
    GpioConfigResponse(GpioConfigResponse),
    /// `gpio_state` (0x42).
    GpioState(GpioState),
    /// `gpio_state_response` (0xC2).
    GpioStateResponse(GpioStateResponse),
    /// `odometer_config` (0x43).
    OdometerConfig(OdometerConfig),
    /// `odometer_config_response` (0xC3).
    OdometerConfigResponse(OdometerConfigResponse),
    /// `advanced_lowpass_filter` (0x50).
    AdvancedLowpassFilter(AdvancedLowpassFilter),
    /// `advanced_lowpass_filter_response` (0x8B).
    AdvancedLowpassFilterResponse(AdvancedLowpassFilterResponse),
    /// `complementary_filter` (0x51).
    ComplementaryFilter(ComplementaryFilter),
    /// `complementary_filter_response` (0x97).
    ComplementaryFilterResponse(ComplementaryFilterResponse),
    /// `sensor_range` (0x52).
    SensorRange(SensorRange),
    /// `sensor_range_response` (0xD2).
    SensorRangeResponse(SensorRangeResponse),
    /// `get_calibrated_sensor_ranges` (0x53).
    GetCalibratedSensorRanges(GetCalibratedSensorRanges),
    /// `calibrated_sensor_ranges` (0xD3).
    CalibratedSensorRanges(CalibratedSensorRanges),
    /// `lowpass_filter` (0x54).
    LowpassFilter(LowpassFilter),
    /// `lowpass_filter_response` (0xD4).
    LowpassFilterResponse(LowpassFilterResponse),
    /// `poll_imu_data` (0x01).
    PollImuData(PollImuData),
    /// `poll_gnss_data` (0x02).
    PollGnssData(PollGnssData),
    /// `poll_filter_data` (0x03).
    PollFilterData(PollFilterData),
    /// `poll_nmea_data` (0x04).
    PollNmeaData(PollNmeaData),
    /// `poll_data` (0x0D).
    PollData(PollData),
    /// `get_imu_base_rate` (0x06).
    GetImuBaseRate(GetImuBaseRate),
    /// `imu_base_rate` (0x83).
    ImuBaseRate(ImuBaseRate),
    /// `get_gnss_base_rate` (0x07).
    GetGnssBaseRate(GetGnssBaseRate),
    /// `gnss_base_rate` (0x84).
    GnssBaseRate(GnssBaseRate),
    /// `get_filter_base_rate` (0x0B).
    GetFilterBaseRate(GetFilterBaseRate),
    /// `filter_base_rate` (0x8A).
    FilterBaseRate(FilterBaseRate),
    /// `get_base_rate` (0x0E).
    GetBaseRate(GetBaseRate),
    /// `base_rate` (0x8E).
    BaseRate(BaseRate),
    /// `imu_message_format` (0x08).
    ImuMessageFormat(ImuMessageFormat),
    /// `imu_message_format_response` (0x80).
    ImuMessageFormatResponse(ImuMessageFormatResponse),
    /// `gnss_message_format` (0x09).
    GnssMessageFormat(GnssMessageFormat),
    /// `gnss_message_format_response` (0x81).
    GnssMessageFormatResponse(GnssMessageFormatResponse),
    /// `filter_message_format` (0x0A).
    FilterMessageFormat(FilterMessageFormat),
    /// `filter_message_format_response` (0x82).
    FilterMessageFormatResponse(FilterMessageFormatResponse),
    /// `nmea_message_format` (0x0C).
    NmeaMessageFormat(NmeaMessageFormat),
    /// `nmea_message_format_response` (0x8C).
    NmeaMessageFormatResponse(NmeaMessageFormatResponse),
    /// `message_format` (0x0F).
    MessageFormat(MessageFormat),
    /// `message_format_response` (0x8F).
    MessageFormatResponse(MessageFormatResponse),
    /// `factory_streaming` (0x10).
    FactoryStreaming(FactoryStreaming),
    /// `data_stream_control` (0x11).
    DataStreamControl(DataStreamControl),
    /// `data_stream_control_response` (0x85).
    DataStreamControlResponse(DataStreamControlResponse),
    /// `raw_rtcm_message` (0x20).
    RawRtcmMessage(RawRtcmMessage),
    /// `gnss_constellation_settings` (0x21).
    GnssConstellationSettings(GnssConstellationSettings),
    /// `gnss_constellation_settings_response` (0xA0).
    GnssConstellationSettingsResponse(GnssConstellationSettingsResponse),
    /// `gnss_sbas_settings` (0x22).
    GnssSbasSettings(GnssSbasSettings),
    /// `gnss_sbas_settings_response` (0xA1).
    GnssSbasSettingsResponse(GnssSbasSettingsResponse),
    /// `gnss_assisted_fix_control` (0x23).
    GnssAssistedFixControl(GnssAssistedFixControl),
    /// `gnss_assisted_fix_control_response` (0xA2).
    GnssAssistedFixControlResponse(GnssAssistedFixControlResponse),
    /// `gnss_assist_time_update` (0x24).
    GnssAssistTimeUpdate(GnssAssistTimeUpdate),
    /// `gnss_assist_time_update_response` (0xA3).
    GnssAssistTimeUpdateResponse(GnssAssistTimeUpdateResponse),
    /// `pps_source` (0x28).
    PpsSource(PpsSource),
    /// `pps_source_response` (0xA8).
    PpsSourceResponse(PpsSourceResponse),
    /// `get_supported_events` (0x2A).
    GetSupportedEvents(GetSupportedEvents),
    /// `supported_events` (0xB4).
    SupportedEvents(SupportedEvents),
    /// `device_status` (0x64).
    DeviceStatus(DeviceStatus),
    /// `device_status_response` (0x90).
    DeviceStatusResponse(DeviceStatusResponse),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::EventControl(_) => 0x2B,
            Self::EventControlResponse(_) => 0xB5,
            Self::GetEventTriggerStatus(_) => 0x2C,
            Self::EventTriggerStatus(_) => 0xB6,
            Self::GetEventActionStatus(_) => 0x2D,
            Self::EventActionStatus(_) => 0xB7,
            Self::EventTriggerConfig(_) => 0x2E,
            Self::EventTriggerConfigResponse(_) => 0xB8,
            Self::EventActionConfig(_) => 0x2F,
            Self::EventActionConfigResponse(_) => 0xB9,
            Self::DeviceStartupSettings(_) => 0x30,
            Self::SensorToVehicleEuler(_) => 0x31,
            Self::SensorToVehicleEulerResponse(_) => 0xB1,
            Self::SensorToVehicleQuaternion(_) => 0x32,
            Self::SensorToVehicleQuaternionResponse(_) => 0xB2,
            Self::SensorToVehicleDcm(_) => 0x33,
            Self::SensorToVehicleDcmResponse(_) => 0xB3,
            Self::AccelBias(_) => 0x37,
            Self::AccelBiasResponse(_) => 0x9A,
            Self::GyroBias(_) => 0x38,
            Self::GyroBiasResponse(_) => 0x9B,
            Self::CaptureGyroBias(_) => 0x39,
            Self::MagHardIronOffset(_) => 0x3A,
            Self::MagHardIronOffsetResponse(_) => 0x9C,
            Self::MagSoftIronMatrix(_) => 0x3B,
            Self::MagSoftIronMatrixResponse(_) => 0x9D,
            Self::ConingScullingEnable(_) => 0x3E,
            Self::ConingScullingEnableResponse(_) => 0x9E,
            Self::UartBaudrate(_) => 0x40,
            Self::UartBaudrateResponse(_) => 0x87,
            Self::GpioConfig(_) => 0x41,
            Self::GpioConfigResponse(_) => 0xC1,
            Self::GpioState(_) => 0x42,
            Self::GpioStateResponse(_) => 0xC2,
            Self::OdometerConfig(_) => 0x43,
            Self::OdometerConfigResponse(_) => 0xC3,
            Self::AdvancedLowpassFilter(_) => 0x50,
            Self::AdvancedLowpassFilterResponse(_) => 0x8B,
            Self::ComplementaryFilter(_) => 0x51,
            Self::ComplementaryFilterResponse(_) => 0x97,
            Self::SensorRange(_) => 0x52,
            Self::SensorRangeResponse(_) => 0xD2,
            Self::GetCalibratedSensorRanges(_) => 0x53,
            Self::CalibratedSensorRanges(_) => 0xD3,
            Self::LowpassFilter(_) => 0x54,
            Self::LowpassFilterResponse(_) => 0xD4,
            Self::PollImuData(_) => 0x01,
            Self::PollGnssData(_) => 0x02,
            Self::PollFilterData(_) => 0x03,
            Self::PollNmeaData(_) => 0x04,
            Self::PollData(_) => 0x0D,
            Self::GetImuBaseRate(_) => 0x06,
            Self::ImuBaseRate(_) => 0x83,
            Self::GetGnssBaseRate(_) => 0x07,
            Self::GnssBaseRate(_) => 0x84,
            Self::GetFilterBaseRate(_) => 0x0B,
            Self::FilterBaseRate(_) => 0x8A,
            Self::GetBaseRate(_) => 0x0E,
            Self::BaseRate(_) => 0x8E,
            Self::ImuMessageFormat(_) => 0x08,
            Self::ImuMessageFormatResponse(_) => 0x80,
            Self::GnssMessageFormat(_) => 0x09,
            Self::GnssMessageFormatResponse(_) => 0x81,
            Self::FilterMessageFormat(_) => 0x0A,
            Self::FilterMessageFormatResponse(_) => 0x82,
            Self::NmeaMessageFormat(_) => 0x0C,
            Self::NmeaMessageFormatResponse(_) => 0x8C,
            Self::MessageFormat(_) => 0x0F,
            Self::MessageFormatResponse(_) => 0x8F,
            Self::FactoryStreaming(_) => 0x10,
            Self::DataStreamControl(_) => 0x11,
            Self::DataStreamControlResponse(_) => 0x85,
            Self::RawRtcmMessage(_) => 0x20,
            Self::GnssConstellationSettings(_) => 0x21,
            Self::GnssConstellationSettingsResponse(_) => 0xA0,
            Self::GnssSbasSettings(_) => 0x22,
            Self::GnssSbasSettingsResponse(_) => 0xA1,
            Self::GnssAssistedFixControl(_) => 0x23,
            Self::GnssAssistedFixControlResponse(_) => 0xA2,
            Self::GnssAssistTimeUpdate(_) => 0x24,
            Self::GnssAssistTimeUpdateResponse(_) => 0xA3,
            Self::PpsSource(_) => 0x28,
            Self::PpsSourceResponse(_) => 0xA8,
            Self::GetSupportedEvents(_) => 0x2A,
            Self::SupportedEvents(_) => 0xB4,
            Self::DeviceStatus(_) => 0x64,
            Self::DeviceStatusResponse(_) => 0x90,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::EventControl(_) => "event_control",
            Self::EventControlResponse(_) => "event_control_response",
            Self::GetEventTriggerStatus(_) => "get_event_trigger_status",
            Self::EventTriggerStatus(_) => "event_trigger_status",
            Self::GetEventActionStatus(_) => "get_event_action_status",
            Self::EventActionStatus(_) => "event_action_status",
            Self::EventTriggerConfig(_) => "event_trigger_config",
            Self::EventTriggerConfigResponse(_) => "event_trigger_config_response",
            Self::EventActionConfig(_) => "event_action_config",
            Self::EventActionConfigResponse(_) => "event_action_config_response",
            Self::DeviceStartupSettings(_) => "device_startup_settings",
            Self::SensorToVehicleEuler(_) => "sensor_to_vehicle_euler",
            Self::SensorToVehicleEulerResponse(_) => "sensor_to_vehicle_euler_response",
            Self::SensorToVehicleQuaternion(_) => "sensor_to_vehicle_quaternion",
            Self::SensorToVehicleQuaternionResponse(_) => "sensor_to_vehicle_quaternion_response",
            Self::SensorToVehicleDcm(_) => "sensor_to_vehicle_dcm",
            Self::SensorToVehicleDcmResponse(_) => "sensor_to_vehicle_dcm_response",
            Self::AccelBias(_) => "accel_bias",
            Self::AccelBiasResponse(_) => "accel_bias_response",
            Self::GyroBias(_) => "gyro_bias",
            Self::GyroBiasResponse(_) => "gyro_bias_response",
            Self::CaptureGyroBias(_) => "capture_gyro_bias",
            Self::MagHardIronOffset(_) => "mag_hard_iron_offset",
            Self::MagHardIronOffsetResponse(_) => "mag_hard_iron_offset_response",
            Self::MagSoftIronMatrix(_) => "mag_soft_iron_matrix",
            Self::MagSoftIronMatrixResponse(_) => "mag_soft_iron_matrix_response",
            Self::ConingScullingEnable(_) => "coning_sculling_enable",
            Self::ConingScullingEnableResponse(_) => "coning_sculling_enable_response",
            Self::UartBaudrate(_) => "uart_baudrate",
            Self::UartBaudrateResponse(_) => "uart_baudrate_response",
            Self::GpioConfig(_) => "gpio_config",
            Self::GpioConfigResponse(_) => "gpio_config_response",
            Self::GpioState(_) => "gpio_state",
            Self::GpioStateResponse(_) => "gpio_state_response",
            Self::OdometerConfig(_) => "odometer_config",
            Self::OdometerConfigResponse(_) => "odometer_config_response",
            Self::AdvancedLowpassFilter(_) => "advanced_lowpass_filter",
            Self::AdvancedLowpassFilterResponse(_) => "advanced_lowpass_filter_response",
            Self::ComplementaryFilter(_) => "complementary_filter",
            Self::ComplementaryFilterResponse(_) => "complementary_filter_response",
            Self::SensorRange(_) => "sensor_range",
            Self::SensorRangeResponse(_) => "sensor_range_response",
            Self::GetCalibratedSensorRanges(_) => "get_calibrated_sensor_ranges",
            Self::CalibratedSensorRanges(_) => "calibrated_sensor_ranges",
            Self::LowpassFilter(_) => "lowpass_filter",
            Self::LowpassFilterResponse(_) => "lowpass_filter_response",
            Self::PollImuData(_) => "poll_imu_data",
            Self::PollGnssData(_) => "poll_gnss_data",
            Self::PollFilterData(_) => "poll_filter_data",
            Self::PollNmeaData(_) => "poll_nmea_data",
            Self::PollData(_) => "poll_data",
            Self::GetImuBaseRate(_) => "get_imu_base_rate",
            Self::ImuBaseRate(_) => "imu_base_rate",
            Self::GetGnssBaseRate(_) => "get_gnss_base_rate",
            Self::GnssBaseRate(_) => "gnss_base_rate",
            Self::GetFilterBaseRate(_) => "get_filter_base_rate",
            Self::FilterBaseRate(_) => "filter_base_rate",
            Self::GetBaseRate(_) => "get_base_rate",
            Self::BaseRate(_) => "base_rate",
            Self::ImuMessageFormat(_) => "imu_message_format",
            Self::ImuMessageFormatResponse(_) => "imu_message_format_response",
            Self::GnssMessageFormat(_) => "gnss_message_format",
            Self::GnssMessageFormatResponse(_) => "gnss_message_format_response",
            Self::FilterMessageFormat(_) => "filter_message_format",
            Self::FilterMessageFormatResponse(_) => "filter_message_format_response",
            Self::NmeaMessageFormat(_) => "nmea_message_format",
            Self::NmeaMessageFormatResponse(_) => "nmea_message_format_response",
            Self::MessageFormat(_) => "message_format",
            Self::MessageFormatResponse(_) => "message_format_response",
            Self::FactoryStreaming(_) => "factory_streaming",
            Self::DataStreamControl(_) => "data_stream_control",
            Self::DataStreamControlResponse(_) => "data_stream_control_response",
            Self::RawRtcmMessage(_) => "raw_rtcm_message",
            Self::GnssConstellationSettings(_) => "gnss_constellation_settings",
            Self::GnssConstellationSettingsResponse(_) => "gnss_constellation_settings_response",
            Self::GnssSbasSettings(_) => "gnss_sbas_settings",
            Self::GnssSbasSettingsResponse(_) => "gnss_sbas_settings_response",
            Self::GnssAssistedFixControl(_) => "gnss_assisted_fix_control",
            Self::GnssAssistedFixControlResponse(_) => "gnss_assisted_fix_control_response",
            Self::GnssAssistTimeUpdate(_) => "gnss_assist_time_update",
            Self::GnssAssistTimeUpdateResponse(_) => "gnss_assist_time_update_response",
            Self::PpsSource(_) => "pps_source",
            Self::PpsSourceResponse(_) => "pps_source_response",
            Self::GetSupportedEvents(_) => "get_supported_events",
            Self::SupportedEvents(_) => "supported_events",
            Self::DeviceStatus(_) => "device_status",
            Self::DeviceStatusResponse(_) => "device_status_response",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::EventControl(_) => None,
            Self::EventControlResponse(_) => None,
            Self::GetEventTriggerStatus(_) => None,
            Self::EventTriggerStatus(_) => None,
            Self::GetEventActionStatus(_) => None,
            Self::EventActionStatus(_) => None,
            Self::EventTriggerConfig(_) => None,
            Self::EventTriggerConfigResponse(_) => None,
            Self::EventActionConfig(_) => None,
            Self::EventActionConfigResponse(_) => None,
            Self::DeviceStartupSettings(v) => Some(v.device()),
            Self::SensorToVehicleEuler(_) => None,
            Self::SensorToVehicleEulerResponse(_) => None,
            Self::SensorToVehicleQuaternion(_) => None,
            Self::SensorToVehicleQuaternionResponse(_) => None,
            Self::SensorToVehicleDcm(_) => None,
            Self::SensorToVehicleDcmResponse(_) => None,
            Self::AccelBias(v) => Some(v.device()),
            Self::AccelBiasResponse(_) => None,
            Self::GyroBias(v) => Some(v.device()),
            Self::GyroBiasResponse(_) => None,
            Self::CaptureGyroBias(_) => None,
            Self::MagHardIronOffset(v) => Some(v.device()),
            Self::MagHardIronOffsetResponse(_) => None,
            Self::MagSoftIronMatrix(v) => Some(v.device()),
            Self::MagSoftIronMatrixResponse(_) => None,
            Self::ConingScullingEnable(_) => None,
            Self::ConingScullingEnableResponse(_) => None,
            Self::UartBaudrate(_) => None,
            Self::UartBaudrateResponse(_) => None,
            Self::GpioConfig(_) => None,
            Self::GpioConfigResponse(_) => None,
            Self::GpioState(_) => None,
            Self::GpioStateResponse(_) => None,
            Self::OdometerConfig(_) => None,
            Self::OdometerConfigResponse(_) => None,
            Self::AdvancedLowpassFilter(_) => None,
            Self::AdvancedLowpassFilterResponse(_) => None,
            Self::ComplementaryFilter(_) => None,
            Self::ComplementaryFilterResponse(_) => None,
            Self::SensorRange(_) => None,
            Self::SensorRangeResponse(_) => None,
            Self::GetCalibratedSensorRanges(_) => None,
            Self::CalibratedSensorRanges(_) => None,
            Self::LowpassFilter(_) => None,
            Self::LowpassFilterResponse(_) => None,
            Self::PollImuData(_) => None,
            Self::PollGnssData(_) => None,
            Self::PollFilterData(_) => None,
            Self::PollNmeaData(_) => None,
            Self::PollData(_) => None,
            Self::GetImuBaseRate(_) => None,
            Self::ImuBaseRate(_) => None,
            Self::GetGnssBaseRate(_) => None,
            Self::GnssBaseRate(_) => None,
            Self::GetFilterBaseRate(_) => None,
            Self::FilterBaseRate(_) => None,
            Self::GetBaseRate(_) => None,
            Self::BaseRate(_) => None,
            Self::ImuMessageFormat(_) => None,
            Self::ImuMessageFormatResponse(_) => None,
            Self::GnssMessageFormat(_) => None,
            Self::GnssMessageFormatResponse(_) => None,
            Self::FilterMessageFormat(_) => None,
            Self::FilterMessageFormatResponse(_) => None,
            Self::NmeaMessageFormat(_) => None,
            Self::NmeaMessageFormatResponse(_) => None,
            Self::MessageFormat(_) => None,
            Self::MessageFormatResponse(_) => None,
            Self::FactoryStreaming(_) => None,
            Self::DataStreamControl(v) => Some(v.device()),
            Self::DataStreamControlResponse(v) => Some(v.device()),
            Self::RawRtcmMessage(_) => None,
            Self::GnssConstellationSettings(_) => None,
            Self::GnssConstellationSettingsResponse(_) => None,
            Self::GnssSbasSettings(_) => None,
            Self::GnssSbasSettingsResponse(_) => None,
            Self::GnssAssistedFixControl(_) => None,
            Self::GnssAssistedFixControlResponse(_) => None,
            Self::GnssAssistTimeUpdate(_) => None,
            Self::GnssAssistTimeUpdateResponse(_) => None,
            Self::PpsSource(_) => None,
            Self::PpsSourceResponse(_) => None,
            Self::GetSupportedEvents(_) => None,
            Self::SupportedEvents(_) => None,
            Self::DeviceStatus(_) => None,
            Self::DeviceStatusResponse(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::EventControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::EventControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetEventTriggerStatus(v) => crate::wire::Layout::encode_data(v, w),
            Self::EventTriggerStatus(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetEventActionStatus(v) => crate::wire::Layout::encode_data(v, w),
            Self::EventActionStatus(v) => crate::wire::Layout::encode_data(v, w),
            Self::EventTriggerConfig(v) => crate::wire::Layout::encode_data(v, w),
            Self::EventTriggerConfigResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::EventActionConfig(v) => crate::wire::Layout::encode_data(v, w),
            Self::EventActionConfigResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeviceStartupSettings(v) => v.encode_data(w),
            Self::SensorToVehicleEuler(v) => crate::wire::Layout::encode_data(v, w),
            Self::SensorToVehicleEulerResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::SensorToVehicleQuaternion(v) => crate::wire::Layout::encode_data(v, w),
            Self::SensorToVehicleQuaternionResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::SensorToVehicleDcm(v) => crate::wire::Layout::encode_data(v, w),
            Self::SensorToVehicleDcmResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::AccelBias(v) => v.encode_data(w),
            Self::AccelBiasResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GyroBias(v) => v.encode_data(w),
            Self::GyroBiasResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::CaptureGyroBias(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagHardIronOffset(v) => v.encode_data(w),
            Self::MagHardIronOffsetResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::MagSoftIronMatrix(v) => v.encode_data(w),
            Self::MagSoftIronMatrixResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::ConingScullingEnable(v) => crate::wire::Layout::encode_data(v, w),
            Self::ConingScullingEnableResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::UartBaudrate(v) => crate::wire::Layout::encode_data(v, w),
            Self::UartBaudrateResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpioConfig(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpioConfigResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpioState(v) => crate::wire::Layout::encode_data(v, w),
            Self::GpioStateResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::OdometerConfig(v) => crate::wire::Layout::encode_data(v, w),
            Self::OdometerConfigResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::AdvancedLowpassFilter(v) => crate::wire::Layout::encode_data(v, w),
            Self::AdvancedLowpassFilterResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::ComplementaryFilter(v) => crate::wire::Layout::encode_data(v, w),
            Self::ComplementaryFilterResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::SensorRange(v) => crate::wire::Layout::encode_data(v, w),
            Self::SensorRangeResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetCalibratedSensorRanges(v) => crate::wire::Layout::encode_data(v, w),
            Self::CalibratedSensorRanges(v) => crate::wire::Layout::encode_data(v, w),
            Self::LowpassFilter(v) => crate::wire::Layout::encode_data(v, w),
            Self::LowpassFilterResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::PollImuData(v) => crate::wire::Layout::encode_data(v, w),
            Self::PollGnssData(v) => crate::wire::Layout::encode_data(v, w),
            Self::PollFilterData(v) => crate::wire::Layout::encode_data(v, w),
            Self::PollNmeaData(v) => crate::wire::Layout::encode_data(v, w),
            Self::PollData(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetImuBaseRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::ImuBaseRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetGnssBaseRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssBaseRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetFilterBaseRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::FilterBaseRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetBaseRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::BaseRate(v) => crate::wire::Layout::encode_data(v, w),
            Self::ImuMessageFormat(v) => crate::wire::Layout::encode_data(v, w),
            Self::ImuMessageFormatResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssMessageFormat(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssMessageFormatResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::FilterMessageFormat(v) => crate::wire::Layout::encode_data(v, w),
            Self::FilterMessageFormatResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::NmeaMessageFormat(v) => crate::wire::Layout::encode_data(v, w),
            Self::NmeaMessageFormatResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::MessageFormat(v) => crate::wire::Layout::encode_data(v, w),
            Self::MessageFormatResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::FactoryStreaming(v) => crate::wire::Layout::encode_data(v, w),
            Self::DataStreamControl(v) => v.encode_data(w),
            Self::DataStreamControlResponse(v) => v.encode_data(w),
            Self::RawRtcmMessage(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssConstellationSettings(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssConstellationSettingsResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssSbasSettings(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssSbasSettingsResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssAssistedFixControl(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssAssistedFixControlResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssAssistTimeUpdate(v) => crate::wire::Layout::encode_data(v, w),
            Self::GnssAssistTimeUpdateResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::PpsSource(v) => crate::wire::Layout::encode_data(v, w),
            Self::PpsSourceResponse(v) => crate::wire::Layout::encode_data(v, w),
            Self::GetSupportedEvents(v) => crate::wire::Layout::encode_data(v, w),
            Self::SupportedEvents(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeviceStatus(v) => crate::wire::Layout::encode_data(v, w),
            Self::DeviceStatusResponse(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::EventControl(v) => crate::wire::Wire::write_json(v, w),
            Self::EventControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GetEventTriggerStatus(v) => crate::wire::Wire::write_json(v, w),
            Self::EventTriggerStatus(v) => crate::wire::Wire::write_json(v, w),
            Self::GetEventActionStatus(v) => crate::wire::Wire::write_json(v, w),
            Self::EventActionStatus(v) => crate::wire::Wire::write_json(v, w),
            Self::EventTriggerConfig(v) => crate::wire::Wire::write_json(v, w),
            Self::EventTriggerConfigResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::EventActionConfig(v) => crate::wire::Wire::write_json(v, w),
            Self::EventActionConfigResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::DeviceStartupSettings(v) => v.write_json(w),
            Self::SensorToVehicleEuler(v) => crate::wire::Wire::write_json(v, w),
            Self::SensorToVehicleEulerResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::SensorToVehicleQuaternion(v) => crate::wire::Wire::write_json(v, w),
            Self::SensorToVehicleQuaternionResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::SensorToVehicleDcm(v) => crate::wire::Wire::write_json(v, w),
            Self::SensorToVehicleDcmResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::AccelBias(v) => v.write_json(w),
            Self::AccelBiasResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GyroBias(v) => v.write_json(w),
            Self::GyroBiasResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::CaptureGyroBias(v) => crate::wire::Wire::write_json(v, w),
            Self::MagHardIronOffset(v) => v.write_json(w),
            Self::MagHardIronOffsetResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::MagSoftIronMatrix(v) => v.write_json(w),
            Self::MagSoftIronMatrixResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::ConingScullingEnable(v) => crate::wire::Wire::write_json(v, w),
            Self::ConingScullingEnableResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::UartBaudrate(v) => crate::wire::Wire::write_json(v, w),
            Self::UartBaudrateResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GpioConfig(v) => crate::wire::Wire::write_json(v, w),
            Self::GpioConfigResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GpioState(v) => crate::wire::Wire::write_json(v, w),
            Self::GpioStateResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::OdometerConfig(v) => crate::wire::Wire::write_json(v, w),
            Self::OdometerConfigResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::AdvancedLowpassFilter(v) => crate::wire::Wire::write_json(v, w),
            Self::AdvancedLowpassFilterResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::ComplementaryFilter(v) => crate::wire::Wire::write_json(v, w),
            Self::ComplementaryFilterResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::SensorRange(v) => crate::wire::Wire::write_json(v, w),
            Self::SensorRangeResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GetCalibratedSensorRanges(v) => crate::wire::Wire::write_json(v, w),
            Self::CalibratedSensorRanges(v) => crate::wire::Wire::write_json(v, w),
            Self::LowpassFilter(v) => crate::wire::Wire::write_json(v, w),
            Self::LowpassFilterResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::PollImuData(v) => crate::wire::Wire::write_json(v, w),
            Self::PollGnssData(v) => crate::wire::Wire::write_json(v, w),
            Self::PollFilterData(v) => crate::wire::Wire::write_json(v, w),
            Self::PollNmeaData(v) => crate::wire::Wire::write_json(v, w),
            Self::PollData(v) => crate::wire::Wire::write_json(v, w),
            Self::GetImuBaseRate(v) => crate::wire::Wire::write_json(v, w),
            Self::ImuBaseRate(v) => crate::wire::Wire::write_json(v, w),
            Self::GetGnssBaseRate(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssBaseRate(v) => crate::wire::Wire::write_json(v, w),
            Self::GetFilterBaseRate(v) => crate::wire::Wire::write_json(v, w),
            Self::FilterBaseRate(v) => crate::wire::Wire::write_json(v, w),
            Self::GetBaseRate(v) => crate::wire::Wire::write_json(v, w),
            Self::BaseRate(v) => crate::wire::Wire::write_json(v, w),
            Self::ImuMessageFormat(v) => crate::wire::Wire::write_json(v, w),
            Self::ImuMessageFormatResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssMessageFormat(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssMessageFormatResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::FilterMessageFormat(v) => crate::wire::Wire::write_json(v, w),
            Self::FilterMessageFormatResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::NmeaMessageFormat(v) => crate::wire::Wire::write_json(v, w),
            Self::NmeaMessageFormatResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::MessageFormat(v) => crate::wire::Wire::write_json(v, w),
            Self::MessageFormatResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::FactoryStreaming(v) => crate::wire::Wire::write_json(v, w),
            Self::DataStreamControl(v) => v.write_json(w),
            Self::DataStreamControlResponse(v) => v.write_json(w),
            Self::RawRtcmMessage(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssConstellationSettings(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssConstellationSettingsResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssSbasSettings(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssSbasSettingsResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssAssistedFixControl(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssAssistedFixControlResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssAssistTimeUpdate(v) => crate::wire::Wire::write_json(v, w),
            Self::GnssAssistTimeUpdateResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::PpsSource(v) => crate::wire::Wire::write_json(v, w),
            Self::PpsSourceResponse(v) => crate::wire::Wire::write_json(v, w),
            Self::GetSupportedEvents(v) => crate::wire::Wire::write_json(v, w),
            Self::SupportedEvents(v) => crate::wire::Wire::write_json(v, w),
            Self::DeviceStatus(v) => crate::wire::Wire::write_json(v, w),
            Self::DeviceStatusResponse(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Decodes field `descriptor` of this set; `None` if the set has no such field.
    pub fn decode(
        descriptor: u8,
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Option<Result<Self, crate::error::DecodeError>> {
        match descriptor {
            0x2B => Some(
                <EventControl as crate::wire::Layout>::decode_data(data).map(Self::EventControl),
            ),
            0xB5 => Some(
                <EventControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::EventControlResponse),
            ),
            0x2C => Some(
                <GetEventTriggerStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::GetEventTriggerStatus),
            ),
            0xB6 => Some(
                <EventTriggerStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::EventTriggerStatus),
            ),
            0x2D => Some(
                <GetEventActionStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::GetEventActionStatus),
            ),
            0xB7 => Some(
                <EventActionStatus as crate::wire::Layout>::decode_data(data)
                    .map(Self::EventActionStatus),
            ),
            0x2E => Some(
                <EventTriggerConfig as crate::wire::Layout>::decode_data(data)
                    .map(Self::EventTriggerConfig),
            ),
            0xB8 => Some(
                <EventTriggerConfigResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::EventTriggerConfigResponse),
            ),
            0x2F => Some(
                <EventActionConfig as crate::wire::Layout>::decode_data(data)
                    .map(Self::EventActionConfig),
            ),
            0xB9 => Some(
                <EventActionConfigResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::EventActionConfigResponse),
            ),
            0x30 => Some(
                DeviceStartupSettings::decode_data(data, device).map(Self::DeviceStartupSettings),
            ),
            0x31 => Some(
                <SensorToVehicleEuler as crate::wire::Layout>::decode_data(data)
                    .map(Self::SensorToVehicleEuler),
            ),
            0xB1 => Some(
                <SensorToVehicleEulerResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SensorToVehicleEulerResponse),
            ),
            0x32 => Some(
                <SensorToVehicleQuaternion as crate::wire::Layout>::decode_data(data)
                    .map(Self::SensorToVehicleQuaternion),
            ),
            0xB2 => Some(
                <SensorToVehicleQuaternionResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SensorToVehicleQuaternionResponse),
            ),
            0x33 => Some(
                <SensorToVehicleDcm as crate::wire::Layout>::decode_data(data)
                    .map(Self::SensorToVehicleDcm),
            ),
            0xB3 => Some(
                <SensorToVehicleDcmResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SensorToVehicleDcmResponse),
            ),
            0x37 => Some(AccelBias::decode_data(data, device).map(Self::AccelBias)),
            0x9A => Some(
                <AccelBiasResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::AccelBiasResponse),
            ),
            0x38 => Some(GyroBias::decode_data(data, device).map(Self::GyroBias)),
            0x9B => Some(
                <GyroBiasResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GyroBiasResponse),
            ),
            0x39 => Some(
                <CaptureGyroBias as crate::wire::Layout>::decode_data(data)
                    .map(Self::CaptureGyroBias),
            ),
            0x3A => Some(MagHardIronOffset::decode_data(data, device).map(Self::MagHardIronOffset)),
            0x9C => Some(
                <MagHardIronOffsetResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagHardIronOffsetResponse),
            ),
            0x3B => Some(MagSoftIronMatrix::decode_data(data, device).map(Self::MagSoftIronMatrix)),
            0x9D => Some(
                <MagSoftIronMatrixResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::MagSoftIronMatrixResponse),
            ),
            0x3E => Some(
                <ConingScullingEnable as crate::wire::Layout>::decode_data(data)
                    .map(Self::ConingScullingEnable),
            ),
            0x9E => Some(
                <ConingScullingEnableResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::ConingScullingEnableResponse),
            ),
            0x40 => Some(
                <UartBaudrate as crate::wire::Layout>::decode_data(data).map(Self::UartBaudrate),
            ),
            0x87 => Some(
                <UartBaudrateResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::UartBaudrateResponse),
            ),
            0x41 => {
                Some(<GpioConfig as crate::wire::Layout>::decode_data(data).map(Self::GpioConfig))
            }
            0xC1 => Some(
                <GpioConfigResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GpioConfigResponse),
            ),
            0x42 => {
                Some(<GpioState as crate::wire::Layout>::decode_data(data).map(Self::GpioState))
            }
            0xC2 => Some(
                <GpioStateResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GpioStateResponse),
            ),
            0x43 => Some(
                <OdometerConfig as crate::wire::Layout>::decode_data(data)
                    .map(Self::OdometerConfig),
            ),
            0xC3 => Some(
                <OdometerConfigResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::OdometerConfigResponse),
            ),
            0x50 => Some(
                <AdvancedLowpassFilter as crate::wire::Layout>::decode_data(data)
                    .map(Self::AdvancedLowpassFilter),
            ),
            0x8B => Some(
                <AdvancedLowpassFilterResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::AdvancedLowpassFilterResponse),
            ),
            0x51 => Some(
                <ComplementaryFilter as crate::wire::Layout>::decode_data(data)
                    .map(Self::ComplementaryFilter),
            ),
            0x97 => Some(
                <ComplementaryFilterResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::ComplementaryFilterResponse),
            ),
            0x52 => {
                Some(<SensorRange as crate::wire::Layout>::decode_data(data).map(Self::SensorRange))
            }
            0xD2 => Some(
                <SensorRangeResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::SensorRangeResponse),
            ),
            0x53 => Some(
                <GetCalibratedSensorRanges as crate::wire::Layout>::decode_data(data)
                    .map(Self::GetCalibratedSensorRanges),
            ),
            0xD3 => Some(
                <CalibratedSensorRanges as crate::wire::Layout>::decode_data(data)
                    .map(Self::CalibratedSensorRanges),
            ),
            0x54 => Some(
                <LowpassFilter as crate::wire::Layout>::decode_data(data).map(Self::LowpassFilter),
            ),
            0xD4 => Some(
                <LowpassFilterResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::LowpassFilterResponse),
            ),
            0x01 => {
                Some(<PollImuData as crate::wire::Layout>::decode_data(data).map(Self::PollImuData))
            }
            0x02 => Some(
                <PollGnssData as crate::wire::Layout>::decode_data(data).map(Self::PollGnssData),
            ),
            0x03 => Some(
                <PollFilterData as crate::wire::Layout>::decode_data(data)
                    .map(Self::PollFilterData),
            ),
            0x04 => Some(
                <PollNmeaData as crate::wire::Layout>::decode_data(data).map(Self::PollNmeaData),
            ),
            0x0D => Some(<PollData as crate::wire::Layout>::decode_data(data).map(Self::PollData)),
            0x06 => Some(
                <GetImuBaseRate as crate::wire::Layout>::decode_data(data)
                    .map(Self::GetImuBaseRate),
            ),
            0x83 => {
                Some(<ImuBaseRate as crate::wire::Layout>::decode_data(data).map(Self::ImuBaseRate))
            }
            0x07 => Some(
                <GetGnssBaseRate as crate::wire::Layout>::decode_data(data)
                    .map(Self::GetGnssBaseRate),
            ),
            0x84 => Some(
                <GnssBaseRate as crate::wire::Layout>::decode_data(data).map(Self::GnssBaseRate),
            ),
            0x0B => Some(
                <GetFilterBaseRate as crate::wire::Layout>::decode_data(data)
                    .map(Self::GetFilterBaseRate),
            ),
            0x8A => Some(
                <FilterBaseRate as crate::wire::Layout>::decode_data(data)
                    .map(Self::FilterBaseRate),
            ),
            0x0E => {
                Some(<GetBaseRate as crate::wire::Layout>::decode_data(data).map(Self::GetBaseRate))
            }
            0x8E => Some(<BaseRate as crate::wire::Layout>::decode_data(data).map(Self::BaseRate)),
            0x08 => Some(
                <ImuMessageFormat as crate::wire::Layout>::decode_data(data)
                    .map(Self::ImuMessageFormat),
            ),
            0x80 => Some(
                <ImuMessageFormatResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::ImuMessageFormatResponse),
            ),
            0x09 => Some(
                <GnssMessageFormat as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssMessageFormat),
            ),
            0x81 => Some(
                <GnssMessageFormatResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssMessageFormatResponse),
            ),
            0x0A => Some(
                <FilterMessageFormat as crate::wire::Layout>::decode_data(data)
                    .map(Self::FilterMessageFormat),
            ),
            0x82 => Some(
                <FilterMessageFormatResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::FilterMessageFormatResponse),
            ),
            0x0C => Some(
                <NmeaMessageFormat as crate::wire::Layout>::decode_data(data)
                    .map(Self::NmeaMessageFormat),
            ),
            0x8C => Some(
                <NmeaMessageFormatResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::NmeaMessageFormatResponse),
            ),
            0x0F => Some(
                <MessageFormat as crate::wire::Layout>::decode_data(data).map(Self::MessageFormat),
            ),
            0x8F => Some(
                <MessageFormatResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::MessageFormatResponse),
            ),
            0x10 => Some(
                <FactoryStreaming as crate::wire::Layout>::decode_data(data)
                    .map(Self::FactoryStreaming),
            ),
            0x11 => Some(DataStreamControl::decode_data(data, device).map(Self::DataStreamControl)),
            0x85 => Some(
                DataStreamControlResponse::decode_data(data, device)
                    .map(Self::DataStreamControlResponse),
            ),
            0x20 => Some(
                <RawRtcmMessage as crate::wire::Layout>::decode_data(data)
                    .map(Self::RawRtcmMessage),
            ),
            0x21 => Some(
                <GnssConstellationSettings as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssConstellationSettings),
            ),
            0xA0 => Some(
                <GnssConstellationSettingsResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssConstellationSettingsResponse),
            ),
            0x22 => Some(
                <GnssSbasSettings as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssSbasSettings),
            ),
            0xA1 => Some(
                <GnssSbasSettingsResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssSbasSettingsResponse),
            ),
            0x23 => Some(
                <GnssAssistedFixControl as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssAssistedFixControl),
            ),
            0xA2 => Some(
                <GnssAssistedFixControlResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssAssistedFixControlResponse),
            ),
            0x24 => Some(
                <GnssAssistTimeUpdate as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssAssistTimeUpdate),
            ),
            0xA3 => Some(
                <GnssAssistTimeUpdateResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::GnssAssistTimeUpdateResponse),
            ),
            0x28 => {
                Some(<PpsSource as crate::wire::Layout>::decode_data(data).map(Self::PpsSource))
            }
            0xA8 => Some(
                <PpsSourceResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::PpsSourceResponse),
            ),
            0x2A => Some(
                <GetSupportedEvents as crate::wire::Layout>::decode_data(data)
                    .map(Self::GetSupportedEvents),
            ),
            0xB4 => Some(
                <SupportedEvents as crate::wire::Layout>::decode_data(data)
                    .map(Self::SupportedEvents),
            ),
            0x64 => Some(
                <DeviceStatus as crate::wire::Layout>::decode_data(data).map(Self::DeviceStatus),
            ),
            0x90 => Some(
                <DeviceStatusResponse as crate::wire::Layout>::decode_data(data)
                    .map(Self::DeviceStatusResponse),
            ),
            _ => None,
        }
    }

    /// Reads the values of field `descriptor` of this set; `None` if the set has no such field.
    #[cfg(feature = "std")]
    pub fn from_json(
        descriptor: u8,
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Option<Result<Self, crate::json_read::JsonError>> {
        match descriptor {
            0x2B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EventControl),
            ),
            0xB5 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EventControlResponse),
            ),
            0x2C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetEventTriggerStatus as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GetEventTriggerStatus),
            ),
            0xB6 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventTriggerStatus as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EventTriggerStatus),
            ),
            0x2D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetEventActionStatus as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GetEventActionStatus),
            ),
            0xB7 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventActionStatus as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EventActionStatus),
            ),
            0x2E => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventTriggerConfig as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EventTriggerConfig),
            ),
            0xB8 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventTriggerConfigResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EventTriggerConfigResponse),
            ),
            0x2F => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventActionConfig as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EventActionConfig),
            ),
            0xB9 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventActionConfigResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::EventActionConfigResponse),
            ),
            0x30 => Some(DeviceStartupSettings::from_json(device, values).map(Self::DeviceStartupSettings)),
            0x31 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleEuler as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleEuler),
            ),
            0xB1 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleEulerResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleEulerResponse),
            ),
            0x32 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleQuaternion as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleQuaternion),
            ),
            0xB2 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleQuaternionResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleQuaternionResponse),
            ),
            0x33 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleDcm as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleDcm),
            ),
            0xB3 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorToVehicleDcmResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorToVehicleDcmResponse),
            ),
            0x37 => Some(AccelBias::from_json(device, values).map(Self::AccelBias)),
            0x9A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AccelBiasResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AccelBiasResponse),
            ),
            0x38 => Some(GyroBias::from_json(device, values).map(Self::GyroBias)),
            0x9B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GyroBiasResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GyroBiasResponse),
            ),
            0x39 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CaptureGyroBias as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::CaptureGyroBias),
            ),
            0x3A => Some(MagHardIronOffset::from_json(device, values).map(Self::MagHardIronOffset)),
            0x9C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagHardIronOffsetResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagHardIronOffsetResponse),
            ),
            0x3B => Some(MagSoftIronMatrix::from_json(device, values).map(Self::MagSoftIronMatrix)),
            0x9D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MagSoftIronMatrixResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MagSoftIronMatrixResponse),
            ),
            0x3E => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ConingScullingEnable as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ConingScullingEnable),
            ),
            0x9E => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ConingScullingEnableResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ConingScullingEnableResponse),
            ),
            0x40 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <UartBaudrate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::UartBaudrate),
            ),
            0x87 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <UartBaudrateResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::UartBaudrateResponse),
            ),
            0x41 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpioConfig as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GpioConfig),
            ),
            0xC1 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpioConfigResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GpioConfigResponse),
            ),
            0x42 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpioState as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GpioState),
            ),
            0xC2 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GpioStateResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GpioStateResponse),
            ),
            0x43 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <OdometerConfig as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::OdometerConfig),
            ),
            0xC3 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <OdometerConfigResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::OdometerConfigResponse),
            ),
            0x50 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AdvancedLowpassFilter as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AdvancedLowpassFilter),
            ),
            0x8B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <AdvancedLowpassFilterResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::AdvancedLowpassFilterResponse),
            ),
            0x51 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ComplementaryFilter as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ComplementaryFilter),
            ),
            0x97 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ComplementaryFilterResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ComplementaryFilterResponse),
            ),
            0x52 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorRange as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorRange),
            ),
            0xD2 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SensorRangeResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SensorRangeResponse),
            ),
            0x53 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetCalibratedSensorRanges as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GetCalibratedSensorRanges),
            ),
            0xD3 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <CalibratedSensorRanges as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::CalibratedSensorRanges),
            ),
            0x54 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <LowpassFilter as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::LowpassFilter),
            ),
            0xD4 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <LowpassFilterResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::LowpassFilterResponse),
            ),
            0x01 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <PollImuData as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::PollImuData),
            ),
            0x02 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <PollGnssData as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::PollGnssData),
            ),
            0x03 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <PollFilterData as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::PollFilterData),
            ),
            0x04 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <PollNmeaData as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::PollNmeaData),
            ),
            0x0D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <PollData as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::PollData),
            ),
            0x06 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetImuBaseRate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GetImuBaseRate),
            ),
            0x83 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ImuBaseRate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ImuBaseRate),
            ),
            0x07 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetGnssBaseRate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GetGnssBaseRate),
            ),
            0x84 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssBaseRate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssBaseRate),
            ),
            0x0B => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetFilterBaseRate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GetFilterBaseRate),
            ),
            0x8A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <FilterBaseRate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::FilterBaseRate),
            ),
            0x0E => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetBaseRate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GetBaseRate),
            ),
            0x8E => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <BaseRate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::BaseRate),
            ),
            0x08 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ImuMessageFormat as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ImuMessageFormat),
            ),
            0x80 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ImuMessageFormatResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::ImuMessageFormatResponse),
            ),
            0x09 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssMessageFormat as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssMessageFormat),
            ),
            0x81 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssMessageFormatResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssMessageFormatResponse),
            ),
            0x0A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <FilterMessageFormat as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::FilterMessageFormat),
            ),
            0x82 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <FilterMessageFormatResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::FilterMessageFormatResponse),
            ),
            0x0C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <NmeaMessageFormat as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::NmeaMessageFormat),
            ),
            0x8C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <NmeaMessageFormatResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::NmeaMessageFormatResponse),
            ),
            0x0F => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MessageFormat as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MessageFormat),
            ),
            0x8F => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <MessageFormatResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::MessageFormatResponse),
            ),
            0x10 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <FactoryStreaming as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::FactoryStreaming),
            ),
            0x11 => Some(DataStreamControl::from_json(device, values).map(Self::DataStreamControl)),
            0x85 => Some(DataStreamControlResponse::from_json(device, values).map(Self::DataStreamControlResponse)),
            0x20 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <RawRtcmMessage as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::RawRtcmMessage),
            ),
            0x21 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssConstellationSettings as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssConstellationSettings),
            ),
            0xA0 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssConstellationSettingsResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssConstellationSettingsResponse),
            ),
            0x22 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssSbasSettings as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssSbasSettings),
            ),
            0xA1 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssSbasSettingsResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssSbasSettingsResponse),
            ),
            0x23 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssAssistedFixControl as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssAssistedFixControl),
            ),
            0xA2 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssAssistedFixControlResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssAssistedFixControlResponse),
            ),
            0x24 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssAssistTimeUpdate as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssAssistTimeUpdate),
            ),
            0xA3 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GnssAssistTimeUpdateResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GnssAssistTimeUpdateResponse),
            ),
            0x28 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <PpsSource as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::PpsSource),
            ),
            0xA8 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <PpsSourceResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::PpsSourceResponse),
            ),
            0x2A => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetSupportedEvents as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::GetSupportedEvents),
            ),
            0xB4 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <SupportedEvents as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::SupportedEvents),
            ),
            0x64 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeviceStatus as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::DeviceStatus),
            ),
            0x90 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <DeviceStatusResponse as crate::json_read::FromJson>::from_json(values).map_err(|e| e.at("values"))
                    })
                    .map(Self::DeviceStatusResponse),
            ),
            _ => None,
        }
    }
}
