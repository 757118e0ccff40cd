"""Golden vectors (generated from tests/vectors/mip/): decode whole and byte by byte, encode back."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

import pytest
from mipcodec import decode_bytes, decode_stream, encode_lines

CASES = [
    {
        "name": "ping_command",
        "hex": "756501020201e0c6",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:8",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}'],
    },
    {
        "name": "ping_reply",
        "hex": "7565010404f10100d56a",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:19",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":1,"ack_code":0}}]}'
        ],
    },
    {
        "name": "set_to_idle_command",
        "hex": "756501020202e1c7",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:30",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":2,"name":"set_to_idle","values":{}}]}'],
    },
    {
        "name": "set_to_idle_copy_paste_published",
        "hex": "756501020201e0c6",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:40",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}'],
    },
    {
        "name": "set_to_idle_reply",
        "hex": "7565010404f10200d66c",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:56",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":2,"ack_code":0}}]}'
        ],
    },
    {
        "name": "get_device_info_command",
        "hex": "756501020203e2c8",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:66",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":3,"name":"get_device_info","values":{}}]}'],
    },
    {
        "name": "get_device_info_reply",
        "hex": "7565015804f10300548105fe33444d2d4758352d3435202020202020363233322d3432373020202020202020363233322d30303132322020202020202020202020202020202020202020202035672c20313530642f73202020202020b801",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:75",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":3,"ack_code":0}},{"descriptor":129,"name":"device_info","values":{"info":{"firmware_version":1534,"model_name":"3DM-GX5-45      ","model_number":"6232-4270       ","serial_number":"6232-00122      ","lot_number":"                ","device_options":"5g, 150d/s      "}}}]}'
        ],
    },
    {
        "name": "get_device_descriptors_command",
        "hex": "756501020204e3c9",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:107",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":4,"name":"get_device_descriptors","values":{}}]}'],
    },
    {
        "name": "get_device_descriptors_reply",
        "hex": "7565011204f104000e820101010201030c010c020c721805",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:116",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":4,"ack_code":0}},{"descriptor":130,"name":"device_descriptors","values":{"descriptors":[257,258,259,3073,3074,3186]}}]}'
        ],
    },
    {
        "name": "get_device_descriptors_reply_empty",
        "hex": "7565010604f1040002825eb4",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:131",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":4,"ack_code":0}},{"descriptor":130,"name":"device_descriptors","values":{"descriptors":[]}}]}'
        ],
    },
    {
        "name": "built_in_test_command",
        "hex": "756501020205e4ca",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:142",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":5,"name":"built_in_test","values":{}}]}'],
    },
    {
        "name": "built_in_test_reply",
        "hex": "7565010a04f10500068300000000687d",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:151",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":5,"ack_code":0}},{"descriptor":131,"name":"built_in_test_result","device":"gx5_45","values":{"flags":0}}]}'
        ],
    },
    {
        "name": "built_in_test_reply_gx5_flags",
        "hex": "7565010a04f105000683010003016d88",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:161",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":5,"ack_code":0}},{"descriptor":131,"name":"built_in_test_result","device":"gx5_45","values":{"flags":16777985}}]}'
        ],
    },
    {
        "name": "resume_command",
        "hex": "756501020206e5cb",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:177",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":6,"name":"resume","values":{}}]}'],
    },
    {
        "name": "resume_reply",
        "hex": "7565010404f10600da74",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:187",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":6,"ack_code":0}}]}'
        ],
    },
    {
        "name": "resume_reply_table_published",
        "hex": "7565010404f10100da74",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mip/base.yaml:196",
        "expect": ['{"offset":0,"skipped":"7565010404f10100da74"}'],
    },
    {
        "name": "get_extended_descriptors_command",
        "hex": "756501020207e6cc",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:209",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":7,"name":"get_extended_descriptors","values":{}}]}'],
    },
    {
        "name": "get_extended_descriptors_table_published",
        "hex": "756501020204e6cc",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mip/base.yaml:218",
        "expect": ['{"offset":0,"skipped":"756501020204e6cc"}'],
    },
    {
        "name": "get_extended_descriptors_reply",
        "hex": "7565010e04f107000a860d270d28822b822c39fc",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:231",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":7,"ack_code":0}},{"descriptor":134,"name":"extended_descriptors","values":{"descriptors":[3367,3368,33323,33324]}}]}'
        ],
    },
    {
        "name": "continuous_bit_command",
        "hex": "756501020208e7cd",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:245",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":8,"name":"continuous_bit","values":{}}]}'],
    },
    {
        "name": "continuous_bit_reply",
        "hex": "7565011604f108001288000102030405060708090a0b0c0d0e0f0082",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:255",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":8,"ack_code":0}},{"descriptor":136,"name":"continuous_bit_result","values":{"result":[0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15]}}]}'
        ],
    },
    {
        "name": "comm_port_speed_write",
        "hex": "75650108080901010001c200b936",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:269",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":9,"name":"comm_port_speed","values":{"function":1,"port":1,"baud":115200}}]}'
        ],
    },
    {
        "name": "comm_port_speed_read",
        "hex": "7565010404090201efb5",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:281",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":9,"name":"comm_port_speed","values":{"function":2,"port":1}}]}'
        ],
    },
    {
        "name": "comm_port_speed_save_all",
        "hex": "7565010404090300efb6",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:292",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":9,"name":"comm_port_speed","values":{"function":3,"port":0}}]}'
        ],
    },
    {
        "name": "comm_port_speed_read_reply",
        "hex": "7565010b04f10900078901000e1000938f",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:302",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":9,"ack_code":0}},{"descriptor":137,"name":"comm_port_speed_response","values":{"port":1,"baud":921600}}]}'
        ],
    },
    {
        "name": "gps_time_update_write_week",
        "hex": "756501080872010100000698fd32",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:315",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":114,"name":"gps_time_update","device":"gx5_45","values":{"function":1,"field_id":1,"value":1688}}]}'
        ],
    },
    {
        "name": "gps_time_update_table_published",
        "hex": "756501080872010000000698fd32",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mip/base.yaml:324",
        "expect": ['{"offset":0,"skipped":"756501080872010000000698fd32"}'],
    },
    {
        "name": "gps_time_update_reply",
        "hex": "7565010404f17200464c",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:337",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":114,"ack_code":0}}]}'
        ],
    },
    {
        "name": "gps_time_update_read_week",
        "hex": "756501040472020158f0",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:346",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":114,"name":"gps_time_update","device":"gx5_45","values":{"function":2,"field_id":1}}]}'
        ],
    },
    {
        "name": "gps_week_reply",
        "hex": "7565010a04f17200068400000698748e",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:358",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":114,"ack_code":0}},{"descriptor":132,"name":"gps_week","values":{"week":1688}}]}'
        ],
    },
    {
        "name": "gps_seconds_reply",
        "hex": "7565010a04f17200068500054600228a",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:371",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":114,"ack_code":0}},{"descriptor":133,"name":"gps_seconds","values":{"seconds":345600}}]}'
        ],
    },
    {
        "name": "gps_time_update_write_no_ack",
        "hex": "756501080872060200054600b04c",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:384",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":114,"name":"gps_time_update","device":"gx5_45","values":{"function":6,"field_id":2,"value":345600}}]}'
        ],
    },
    {
        "name": "device_reset_command",
        "hex": "75650102027e5d43",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:396",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":126,"name":"device_reset","values":{}}]}'],
    },
    {
        "name": "device_reset_reply",
        "hex": "7565010404f17e005264",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:405",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":126,"ack_code":0}}]}'
        ],
    },
    {
        "name": "nack_invalid_parameter",
        "hex": "7565010404f17e035567",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:414",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":126,"ack_code":3}}]}'
        ],
    },
    {
        "name": "two_commands_one_packet",
        "hex": "7565010402010202e696",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:425",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}},{"descriptor":2,"name":"set_to_idle","values":{}}]}'
        ],
    },
    {
        "name": "gps_time_update_write_week_cv7",
        "hex": "756501080872010100000698fd32",
        "device": "cv7_ins",
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:438",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":114,"name":"gps_time_update","device":"cv7_ins","values":{"function":1,"field_id":1,"value":1688}}]}'
        ],
    },
    {
        "name": "built_in_test_reply_cv7_flags",
        "hex": "7565010a04f10500068300802000083d",
        "device": "cv7_ins",
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:452",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":5,"ack_code":0}},{"descriptor":131,"name":"built_in_test_result","device":"cv7_ins","values":{"flags":8396800}}]}'
        ],
    },
    {
        "name": "device_info_every_string_byte",
        "hex": "756501545481ffff5122425c00011f7f80ff7e20090a0d5a0000000000000000000000000000000020202020202020202020202020202020202122232425262728292a2b2c2d2e2ff0f1f2f3f4f5f6f7f8f9fafbfcfdfeff39e6",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:466",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":129,"name":"device_info","values":{"info":{"firmware_version":65535,"model_name":"Q\\"B\\\\\\u0000\\u0001\\u001f\\u007f\\u0080\\u00ff~ \\u0009\\u000a\\u000dZ","model_number":"\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000\\u0000","serial_number":"                ","lot_number":" !\\"#$%&\'()*+,-./","device_options":"\\u00f0\\u00f1\\u00f2\\u00f3\\u00f4\\u00f5\\u00f6\\u00f7\\u00f8\\u00f9\\u00fa\\u00fb\\u00fc\\u00fd\\u00fe\\u00ff"}}}]}'
        ],
    },
    {
        "name": "ack_imu_message_format",
        "hex": "75650c0404f10800e7ba",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:493",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":8,"ack_code":0}}]}'
        ],
    },
    {
        "name": "ack_filter_message_format",
        "hex": "75650c0404f10a00e9be",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:501",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":10,"ack_code":0}}]}'
        ],
    },
    {
        "name": "two_acks_save_formats_published",
        "hex": "75650c0804f1080004f10a00e9be",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mip/base.yaml:509",
        "expect": ['{"offset":0,"skipped":"75650c0804f1080004f10a00e9be"}'],
    },
    {
        "name": "two_acks_save_formats",
        "hex": "75650c0804f1080004f10a00ea71",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:521",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":8,"ack_code":0}},{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":10,"ack_code":0}}]}'
        ],
    },
    {
        "name": "two_acks_enable_streams",
        "hex": "75650c0804f1110004f11100fab5",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:533",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":17,"ack_code":0}},{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":17,"ack_code":0}}]}'
        ],
    },
    {
        "name": "ack_poll_data",
        "hex": "75650c0404f10100e0ac",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:542",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":1,"ack_code":0}}]}'
        ],
    },
    {
        "name": "ack_initialize_attitude",
        "hex": "75650d0404f10200e2b4",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:552",
        "expect": [
            '{"offset":0,"set":13,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":2,"ack_code":0}}]}'
        ],
    },
    {
        "name": "ack_pps_source",
        "hex": "75650c0404f1280007fa",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/base.yaml:560",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":40,"ack_code":0}}]}'
        ],
    },
    {
        "name": "event_trigger_gpio_edge",
        "hex": "75650c07072e01010101042af4",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:6",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":1,"type":1,"parameters":{"pin":1,"mode":4}}}]}'
        ],
    },
    {
        "name": "event_action_message_sensor",
        "hex": "75650c0f0f2f0101010280000005d0d5d6070847ca",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:16",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":47,"name":"event_action_config","values":{"function":1,"instance":1,"trigger":1,"type":2,"parameters":{"desc_set":128,"decimation":0,"num_fields":5,"descriptors":[208,213,214,7,8]}}}]}'
        ],
    },
    {
        "name": "event_action_message_filter",
        "hex": "75650c0e0e2f0102010282000004d0d5d6053d7a",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:31",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":47,"name":"event_action_config","values":{"function":1,"instance":2,"trigger":1,"type":2,"parameters":{"desc_set":130,"decimation":0,"num_fields":4,"descriptors":[208,213,214,5]}}}]}'
        ],
    },
    {
        "name": "event_control_enable_1",
        "hex": "75650c05052b0101011e82",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:46",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":43,"name":"event_control","values":{"function":1,"instance":1,"mode":1}}]}'
        ],
    },
    {
        "name": "event_action_gpio_active_high",
        "hex": "75650c08082f0101010101012b31",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:58",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":47,"name":"event_action_config","values":{"function":1,"instance":1,"trigger":1,"type":1,"parameters":{"pin":1,"mode":1}}}]}'
        ],
    },
    {
        "name": "event_trigger_threshold_interval",
        "hex": "75650c19192e01010280d50102415fca0540000000416fca0560000000308a",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:68",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":1,"type":2,"parameters":{"desc_set":128,"field_desc":213,"param_id":1,"type":2,"low_thres":8333333.0,"high_thres":16666667.0}}}]}'
        ],
    },
    {
        "name": "event_trigger_gpio_while_low",
        "hex": "75650c07072e01010103022af6",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:85",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":1,"type":1,"parameters":{"pin":3,"mode":2}}}]}'
        ],
    },
    {
        "name": "get_event_trigger_status_1",
        "hex": "75650c04042c01011c5e",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:95",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":44,"name":"get_event_trigger_status","values":{"requested_count":1,"requested_instances":[1]}}]}'
        ],
    },
    {
        "name": "event_trigger_status_enabled",
        "hex": "75650c0904f12c0005b6010102cf63",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:103",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":44,"ack_code":0}},{"descriptor":182,"name":"event_trigger_status","values":{"count":1,"triggers":[{"type":1,"status":2}]}}]}'
        ],
    },
    {
        "name": "event_trigger_status_active",
        "hex": "75650c0904f12c0005b6010103d064",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:119",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":44,"ack_code":0}},{"descriptor":182,"name":"event_trigger_status","values":{"count":1,"triggers":[{"type":1,"status":3}]}}]}'
        ],
    },
    {
        "name": "event_action_message_decimated_sensor",
        "hex": "75650c0c0c2f0101010280000a020405c778",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:128",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":47,"name":"event_action_config","values":{"function":1,"instance":1,"trigger":1,"type":2,"parameters":{"desc_set":128,"decimation":10,"num_fields":2,"descriptors":[4,5]}}}]}'
        ],
    },
    {
        "name": "event_action_message_decimated_filter",
        "hex": "75650c0b0b2f0102010282000a0105c3ab",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:143",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":47,"name":"event_action_config","values":{"function":1,"instance":2,"trigger":1,"type":2,"parameters":{"desc_set":130,"decimation":10,"num_fields":1,"descriptors":[5]}}}]}'
        ],
    },
    {
        "name": "event_action_gpio_oneshot_high",
        "hex": "75650c08082f010101010405323b",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:158",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":47,"name":"event_action_config","values":{"function":1,"instance":1,"trigger":1,"type":1,"parameters":{"pin":4,"mode":5}}}]}'
        ],
    },
    {
        "name": "event_trigger_threshold_roll_45",
        "hex": "75650c19192e010102800c01013fe921fb323ae5afbfe921fb323ae5afe040",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:168",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":1,"type":2,"parameters":{"desc_set":128,"field_desc":12,"param_id":1,"type":1,"low_thres":0.7853981,"high_thres":-0.7853981}}}]}'
        ],
    },
    {
        "name": "event_trigger_threshold_pitch_45",
        "hex": "75650c19192e010202800c02013fe921fb323ae5afbfe921fb323ae5afe268",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:182",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":2,"type":2,"parameters":{"desc_set":128,"field_desc":12,"param_id":2,"type":1,"low_thres":0.7853981,"high_thres":-0.7853981}}}]}'
        ],
    },
    {
        "name": "event_control_enable_2",
        "hex": "75650c05052b0102011f84",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:196",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":43,"name":"event_control","values":{"function":1,"instance":2,"mode":1}}]}'
        ],
    },
    {
        "name": "event_trigger_combination_any",
        "hex": "75650c0b0b2e010303fffe0102000031f6",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:207",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":3,"type":3,"parameters":{"logic_table":65534,"input_triggers":[1,2,0,0]}}}]}'
        ],
    },
    {
        "name": "event_control_enable_3",
        "hex": "75650c05052b0103012086",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:229",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":43,"name":"event_control","values":{"function":1,"instance":3,"mode":1}}]}'
        ],
    },
    {
        "name": "event_action_gpio_trigger_3",
        "hex": "75650c08082f010103010401303f",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:239",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":47,"name":"event_action_config","values":{"function":1,"instance":1,"trigger":3,"type":1,"parameters":{"pin":4,"mode":1}}}]}'
        ],
    },
    {
        "name": "event_trigger_threshold_roll_10",
        "hex": "75650c19192e010202800c0101bfc6571814c9bba03fc6571814c9bba0b1fa",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:251",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":2,"type":2,"parameters":{"desc_set":128,"field_desc":12,"param_id":1,"type":1,"low_thres":-0.1745329,"high_thres":0.1745329}}}]}'
        ],
    },
    {
        "name": "event_trigger_combination_latch",
        "hex": "75650c0b0b2e010303cece03010200d3e9",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:267",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":3,"type":3,"parameters":{"logic_table":52942,"input_triggers":[3,1,2,0]}}}]}'
        ],
    },
    {
        "name": "event_action_gpio_oneshot_low",
        "hex": "75650c08082f0102020104063545",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:277",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":47,"name":"event_action_config","values":{"function":1,"instance":2,"trigger":2,"type":1,"parameters":{"pin":4,"mode":6}}}]}'
        ],
    },
    {
        "name": "event_trigger_config_read",
        "hex": "75650c04042e02011f66",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:287",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":2,"instance":1}}]}'
        ],
    },
    {
        "name": "event_trigger_config_read_reply_none",
        "hex": "75650c0804f12e0004b80100ce98",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:298",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":46,"ack_code":0}},{"descriptor":184,"name":"event_trigger_config_response","values":{"instance":1,"type":0,"parameters":null}}]}'
        ],
    },
    {
        "name": "get_event_action_status_all_reply",
        "hex": "75650c0b04f12d0007b70202010103da41",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:311",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":45,"ack_code":0}},{"descriptor":183,"name":"event_action_status","values":{"count":2,"actions":[{"action_type":2,"trigger_id":1},{"action_type":1,"trigger_id":3}]}}]}'
        ],
    },
    {
        "name": "doubles_power_of_two_and_negative_zero",
        "hex": "75650c19192e010402800c010116900000000000008000000000000000014c",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:329",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":4,"type":2,"parameters":{"desc_set":128,"field_desc":12,"param_id":1,"type":1,"low_thres":5.225680706521042e-200,"high_thres":-0.0}}}]}'
        ],
    },
    {
        "name": "doubles_denormal_and_1e16",
        "hex": "75650c19192e010402800c010100000000000000014341c37937e0800033cf",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:343",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":4,"type":2,"parameters":{"desc_set":128,"field_desc":12,"param_id":1,"type":1,"low_thres":5e-324,"high_thres":1e+16}}}]}'
        ],
    },
    {
        "name": "doubles_positional_boundary",
        "hex": "75650c19192e010402800c01013f1a36e2eb1c432d3ee4f8b588e368f156da",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:354",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":4,"type":2,"parameters":{"desc_set":128,"field_desc":12,"param_id":1,"type":1,"low_thres":0.0001,"high_thres":1e-05}}}]}'
        ],
    },
    {
        "name": "doubles_large_values",
        "hex": "75650c19192e010402800c01017e37e43c8800759c42dc12218377de6bdd44",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:365",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":4,"type":2,"parameters":{"desc_set":128,"field_desc":12,"param_id":1,"type":1,"low_thres":1e+300,"high_thres":123456789012345.67}}}]}'
        ],
    },
    {
        "name": "doubles_infinity_and_nan_payload",
        "hex": "75650c19192e010402800c01017ff0000000000000fff00000000000013a05",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/events.yaml:376",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"name":"event_trigger_config","values":{"function":1,"instance":4,"type":2,"parameters":{"desc_set":128,"field_desc":12,"param_id":1,"type":1,"low_thres":"inf","high_thres":"nan:0xfff0000000000001"}}}]}'
        ],
    },
    {
        "name": "overview_field_descriptor_0x03",
        "hex": "7565800e0e033e7a63a0bb8e3b297fe5bf7f83e1",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/sensor.yaml:9",
        "expect": [
            '{"offset":0,"set":128,"fields":[{"descriptor":3,"data":"3e7a63a0bb8e3b297fe5bf7f","error":"unknown descriptor"}]}'
        ],
    },
    {
        "name": "overview_scaled_mag",
        "hex": "7565800e0e063e7a63a0bb8e3b297fe5bf7f8608",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/sensor.yaml:23",
        "expect": [
            '{"offset":0,"set":128,"fields":[{"descriptor":6,"name":"scaled_mag","values":{"scaled_mag":[0.2445206642150879,-0.004340548533946276,"nan:0x7fe5bf7f"]}}]}'
        ],
    },
    {
        "name": "overview_gyro_mag_published",
        "hex": "7565801c0e053e7a63a0bb8e3b297fe5bf7f0e063e7a63a0bb8e3b297fe5bf7fe0c6",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mip/sensor.yaml:33",
        "expect": ['{"offset":0,"skipped":"7565801c0e053e7a63a0bb8e3b297fe5bf7f0e063e7a63a0bb8e3b297fe5bf7fe0c6"}'],
    },
    {
        "name": "overview_gyro_mag",
        "hex": "7565801c0e053e7a63a0bb8e3b297fe5bf7f0e063e7a63a0bb8e3b297fe5bf7fb11e",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/sensor.yaml:46",
        "expect": [
            '{"offset":0,"set":128,"fields":[{"descriptor":5,"name":"scaled_gyro","values":{"scaled_gyro":[0.2445206642150879,-0.004340548533946276,"nan:0x7fe5bf7f"]}},{"descriptor":6,"name":"scaled_mag","values":{"scaled_mag":[0.2445206642150879,-0.004340548533946276,"nan:0x7fe5bf7f"]}}]}'
        ],
    },
    {
        "name": "scaled_accel_example_gx5_published",
        "hex": "7565800e0e043e7a63a0bb8e3b297fe5bf7f92c0",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mip/sensor.yaml:57",
        "expect": ['{"offset":0,"skipped":"7565800e0e043e7a63a0bb8e3b297fe5bf7f92c0"}'],
    },
    {
        "name": "scaled_accel_example",
        "hex": "7565800e0e043e7a63a0bb8e3b297fe5bf7f84ee",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/sensor.yaml:69",
        "expect": [
            '{"offset":0,"set":128,"fields":[{"descriptor":4,"name":"scaled_accel","values":{"scaled_accel":[0.2445206642150879,-0.004340548533946276,"nan:0x7fe5bf7f"]}}]}'
        ],
    },
    {
        "name": "poll_imu_data_packet_published",
        "hex": "7565801c0e043e7a63a0bb8e3b297fe5bf7f0e033e7a63a0bb8e3b297fe5bf7f41bb",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mip/sensor.yaml:78",
        "expect": ['{"offset":0,"skipped":"7565801c0e043e7a63a0bb8e3b297fe5bf7f0e033e7a63a0bb8e3b297fe5bf7f41bb"}'],
    },
    {
        "name": "poll_imu_data_packet_as_printed",
        "hex": "7565801c0e043e7a63a0bb8e3b297fe5bf7f0e033e7a63a0bb8e3b297fe5bf7faddc",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/sensor.yaml:91",
        "expect": [
            '{"offset":0,"set":128,"fields":[{"descriptor":4,"name":"scaled_accel","values":{"scaled_accel":[0.2445206642150879,-0.004340548533946276,"nan:0x7fe5bf7f"]}},{"descriptor":3,"data":"3e7a63a0bb8e3b297fe5bf7f","error":"unknown descriptor"}]}'
        ],
    },
    {
        "name": "poll_imu_data_packet_corrected",
        "hex": "7565801c0e053e7a63a0bb8e3b297fe5bf7f0e043e7a63a0bb8e3b297fe5bf7faf04",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/sensor.yaml:109",
        "expect": [
            '{"offset":0,"set":128,"fields":[{"descriptor":5,"name":"scaled_gyro","values":{"scaled_gyro":[0.2445206642150879,-0.004340548533946276,"nan:0x7fe5bf7f"]}},{"descriptor":4,"name":"scaled_accel","values":{"scaled_accel":[0.2445206642150879,-0.004340548533946276,"nan:0x7fe5bf7f"]}}]}'
        ],
    },
    {
        "name": "accel_gyro_mag_typical",
        "hex": "7565802a0e043f800000bf000000000000000e053e8000003a83126fc00000000e063f0000003e000000bec00000f2e2",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/sensor.yaml:122",
        "expect": [
            '{"offset":0,"set":128,"fields":[{"descriptor":4,"name":"scaled_accel","values":{"scaled_accel":[1.0,-0.5,0.0]}},{"descriptor":5,"name":"scaled_gyro","values":{"scaled_gyro":[0.25,0.0010000000474974513,-2.0]}},{"descriptor":6,"name":"scaled_mag","values":{"scaled_mag":[0.5,0.125,-0.375]}}]}'
        ],
    },
    {
        "name": "garbage_around_ping",
        "hex": "00ff756501020201e0c675",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/streams.yaml:5",
        "expect": [
            '{"offset":0,"skipped":"00ff"}',
            '{"offset":2,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}',
            '{"offset":10,"skipped":"75"}',
        ],
    },
    {
        "name": "false_sync_running_past_the_end",
        "hex": "75650110756501020201e0c6",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/streams.yaml:19",
        "expect": [
            '{"offset":0,"skipped":"75650110"}',
            '{"offset":4,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}',
        ],
    },
    {
        "name": "bad_checksum_then_valid",
        "hex": "756501020201e0c77565010404f10100d56a",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/streams.yaml:32",
        "expect": [
            '{"offset":0,"skipped":"756501020201e0c7"}',
            '{"offset":8,"set":1,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":1,"ack_code":0}}]}',
        ],
    },
    {
        "name": "packet_inside_false_packet",
        "hex": "7565010a756501020201e0c600000000",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/streams.yaml:45",
        "expect": [
            '{"offset":0,"skipped":"7565010a"}',
            '{"offset":4,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}',
            '{"offset":12,"skipped":"00000000"}',
        ],
    },
    {
        "name": "truncated_packet_at_end",
        "hex": "7565010404f1",
        "device": None,
        "rejected": True,
        "where": "tests/vectors/mip/streams.yaml:61",
        "expect": ['{"offset":0,"skipped":"7565010404f1"}'],
    },
    {
        "name": "field_length_overruns_payload",
        "hex": "7565010402010302e798",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/streams.yaml:66",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}},{"trailing":"0302","error":"field length 3 at payload offset 2 overruns the payload (2 bytes left)"}]}'
        ],
    },
    {
        "name": "field_length_below_header",
        "hex": "756501020101dfc4",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/streams.yaml:78",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"trailing":"0101","error":"field length 1 at payload offset 0 is shorter than the field header"}]}'
        ],
    },
    {
        "name": "field_too_short_for_type",
        "hex": "7565800a0a043f800000bf000000f0f1",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/streams.yaml:88",
        "expect": [
            '{"offset":0,"set":128,"fields":[{"descriptor":4,"data":"3f800000bf000000","error":"scaled_accel[2]: needs 4 bytes at offset 8, 0 left"}]}'
        ],
    },
    {
        "name": "field_with_trailing_bytes",
        "hex": "756501030302553804",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/streams.yaml:99",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":2,"data":"55","error":"1 unexpected bytes at offset 0"}]}'
        ],
    },
    {
        "name": "unknown_set_and_descriptor",
        "hex": "7565a70404331234026a",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/streams.yaml:109",
        "expect": [
            '{"offset":0,"set":167,"fields":[{"descriptor":51,"data":"1234","error":"unknown descriptor set"}]}'
        ],
    },
    {
        "name": "ack_in_undefined_command_set",
        "hex": "75657f0404f11000627c",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/streams.yaml:119",
        "expect": [
            '{"offset":0,"set":127,"fields":[{"descriptor":241,"name":"ack_nack","values":{"command_descriptor":16,"ack_code":0}}]}'
        ],
    },
    {
        "name": "union_selector_without_member",
        "hex": "75650c07072e0101090104320c",
        "device": None,
        "rejected": False,
        "where": "tests/vectors/mip/streams.yaml:130",
        "expect": [
            '{"offset":0,"set":12,"fields":[{"descriptor":46,"data":"0101090104","error":"parameters: no member for selector value 9"}]}'
        ],
    },
]


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_decode_whole(case):
    assert decode_bytes(bytes.fromhex(case["hex"]), case["device"]) == case["expect"], case["where"]


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_decode_byte_by_byte(case):
    data = bytes.fromhex(case["hex"])
    lines = list(decode_stream((data[i : i + 1] for i in range(len(data))), case["device"]))
    assert lines == case["expect"], case["where"]


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_encode(case):
    assert encode_lines(case["expect"]).hex() == case["hex"], case["where"]
