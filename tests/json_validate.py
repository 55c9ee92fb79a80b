"""json_validate.py SCHEMA_DIR SCHEMA valid|invalid FILE...: every FILE valid against
SCHEMA_DIR/SCHEMA (JSON Schema draft 2020-12; each error printed with its JSON path),
or every FILE rejected. Exit 0 as expected, 1 not. Needs python3-jsonschema."""
import json, pathlib, sys
import jsonschema

schema_dir, name, expect, files = pathlib.Path(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4:]
# the schemas refer to each other by file name: each is known by its file's URI
store = {p.resolve().as_uri(): json.loads(p.read_text()) for p in schema_dir.glob("*.schema.json")}
for schema in store.values():
    jsonschema.Draft202012Validator.check_schema(schema)
root = {"$ref": (schema_dir / name).resolve().as_uri()}
try:
    from referencing import Registry, Resource
    refs = {"registry": Registry().with_resources(
        (uri, Resource.from_contents(s)) for uri, s in store.items())}
except ImportError:  # jsonschema before 4.18 (Debian bookworm's 4.10)
    refs = {"resolver": jsonschema.RefResolver("", root, store=store)}
validator = jsonschema.Draft202012Validator(root, format_checker=jsonschema.FormatChecker(), **refs)

def explain(f, e, indent=""):
    """error e with its JSON path, then why each of its alternatives (oneOf) failed"""
    text = e.message if len(e.message) < 160 else f"fails {e.validator}: {json.dumps(e.validator_value)[:100]}"
    print(f"{indent}{f}: {e.json_path}: {text}")
    for sub in e.context:
        explain(f, sub, indent + "  ")

failed = False
for f in files:
    errors = list(validator.iter_errors(json.loads(pathlib.Path(f).read_text())))
    if expect == "valid":
        for e in errors:
            explain(f, e)
    elif not errors:
        print(f"{f}: accepted by {name}, should be rejected")
    failed |= bool(errors) != (expect == "invalid")
sys.exit(failed)
