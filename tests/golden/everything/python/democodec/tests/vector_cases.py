"""Golden vectors and stream corpus of democodec (generated from tests/vectors/demo/ and
tests/streams/demo/), checked by tests/test_vectors.py."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

import democodec as package

__all__ = ["CASES", "package"]

CASES = [
    {
        "name": "demo_ping_command",
        "hex": "a5a5010201004e23",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:11",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}'],
    },
    {
        "name": "demo_ack",
        "hex": "a5a5010480020100d2cd",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:22",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"echo":1,"code":0}}]}'],
    },
    {
        "name": "demo_configure_write_gpio",
        "hex": "a5a501080206010101050100647f",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:32",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":2,"name":"configure","values":{"function":1,"instance":1,"mode":1,"params":{"pin":5,"polarity":true},"suppress_ack":false}}]}'
        ],
    },
    {
        "name": "demo_configure_write_none",
        "hex": "a5a501060204010200015b9c",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:45",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":2,"name":"configure","values":{"function":1,"instance":2,"mode":0,"params":null,"suppress_ack":true}}]}'
        ],
    },
    {
        "name": "demo_configure_read",
        "hex": "a5a501040202020358da",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:55",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":2,"name":"configure","values":{"function":2,"instance":3}}]}'
        ],
    },
    {
        "name": "demo_configuration_response",
        "hex": "a5a5017f827d0102006400c8616263000000000020202020202020202020206c6162656c3ff00000000000000000000000000000000000000000000000000000000000003ff00000000000000000000000000000000000000000000000000000000000003ff000000000000000000001ffffffff00000002fffffffe3001ffff78797a9f15",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:65",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":130,"name":"configuration","values":{"instance":1,"count":2,"rates":[100,200],"name":"abc\\u0000\\u0000\\u0000\\u0000\\u0000","label":"           label","matrix":[1.0,0.0,0.0,0.0,1.0,0.0,0.0,0.0,1.0],"fixed":[1,-1,2,-2],"flags":12289,"signed":-1,"tail":["x","y","z"]}}]}'
        ],
    },
    {
        "name": "demo_per_device_dev_a",
        "hex": "a5a5010603040102030462ab",
        "device": "dev_a",
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:97",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":3,"name":"per_device","device":"dev_a","values":{"a":16909060}}]}'
        ],
    },
    {
        "name": "demo_per_device_dev_b_with_extra",
        "hex": "a5a5010b03090000000000000001076ac6",
        "device": "dev_b",
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:108",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":3,"name":"per_device","device":"dev_b","values":{"b":1,"extra":7}}]}'
        ],
    },
    {
        "name": "demo_per_device_dev_b_without_extra",
        "hex": "a5a5010a030800000000000000ff5f46",
        "device": "dev_b",
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:119",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":3,"name":"per_device","device":"dev_b","values":{"b":255}}]}'
        ],
    },
    {
        "name": "demo_sample_repeated",
        "hex": "a5a5903e011d3f8000000000000000000000000000000102030405060708fe3f000000011d0000000000000000000000003f80000000000000000000007fbf800000f1a4",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:130",
        "expect": [
            '{"offset":0,"set":144,"fields":[{"descriptor":1,"name":"sample","values":{"quat":[1.0,0.0,0.0,0.0],"big":72623859790382856,"small":-2,"f":0.5}},{"descriptor":1,"name":"sample","values":{"quat":[0.0,0.0,0.0,1.0],"big":0,"small":127,"f":-1.0}}]}'
        ],
    },
    {
        "name": "demo_receiver_1_shared_and_layout",
        "hex": "a5a5911ed308000000003b9aca0003124046c00000000000c05e90000000000000037f56",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:147",
        "expect": [
            '{"offset":0,"set":145,"fields":[{"descriptor":211,"name":"timestamp","values":{"nanoseconds":1000000000}},{"descriptor":3,"name":"llh_position","values":{"latitude":45.5,"longitude":-122.25,"valid_flags":3}}]}'
        ],
    },
    {
        "name": "demo_receiver_2_same_layout",
        "hex": "a5a5921403124046c00000000000c05e9000000000000003fc84",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:161",
        "expect": [
            '{"offset":0,"set":146,"fields":[{"descriptor":3,"name":"llh_position","values":{"latitude":45.5,"longitude":-122.25,"valid_flags":3}}]}'
        ],
    },
    {
        "name": "demo_ping_bad_checksum",
        "hex": "a5a5010201004f23",
        "device": None,
        "rejected": True,
        "where": "tests/golden/vectors/demo/everything.yaml:171",
        "expect": ['{"offset":0,"skipped":"a5a5010201004f23"}'],
    },
]
