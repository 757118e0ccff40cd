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
    const NAME: &'static str = "event_action_config_response";
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
        }
    }

    /// Decodes field `descriptor` of this set; `None` if the set has no such field.
    pub fn decode(
        descriptor: u8,
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Option<Result<Self, crate::error::DecodeError>> {
        let _ = device;
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
                        <EventControl as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EventControl),
            ),
            0xB5 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventControlResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EventControlResponse),
            ),
            0x2C => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetEventTriggerStatus as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GetEventTriggerStatus),
            ),
            0xB6 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventTriggerStatus as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EventTriggerStatus),
            ),
            0x2D => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <GetEventActionStatus as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::GetEventActionStatus),
            ),
            0xB7 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventActionStatus as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EventActionStatus),
            ),
            0x2E => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventTriggerConfig as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EventTriggerConfig),
            ),
            0xB8 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventTriggerConfigResponse as crate::json_read::FromJson>::from_json(
                            values,
                        )
                        .map_err(|e| e.at("values"))
                    })
                    .map(Self::EventTriggerConfigResponse),
            ),
            0x2F => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventActionConfig as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EventActionConfig),
            ),
            0xB9 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <EventActionConfigResponse as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::EventActionConfigResponse),
            ),
            _ => None,
        }
    }
}
