"""The dolfinx scripts' report: the results printed a key per line, and
written as JSON when asked (dolfinx_mandel.py, dolfinx_heat.py)."""
import json


def report(result, json_path, width):
    for key, value in result.items():
        if isinstance(value, float):
            print("%-*s %.15g" % (width, key, value))
        else:
            print("%-*s %s" % (width, key, value))
    if json_path:
        with open(json_path, "w") as out:
            json.dump(result, out, indent=2)
            out.write("\n")
