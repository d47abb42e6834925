// Validates JSON files against schema/sweep.schema.json with ajv (draft 2020-12).
// Usage: node validate.mjs SCHEMA FILE...   prints "<file> valid|invalid <first error>" per file.
import { readFileSync } from "node:fs";
import Ajv2020 from "ajv/dist/2020.js";
const [schemaPath, ...files] = process.argv.slice(2);
const ajv = new Ajv2020({ allErrors: false, strict: false });
const validate = ajv.compile(JSON.parse(readFileSync(schemaPath, "utf8")));
for (const f of files) {
  let data;
  try {
    data = JSON.parse(readFileSync(f, "utf8"));
  } catch (e) {
    console.log(`${f} invalid not JSON`);
    continue;
  }
  const ok = validate(data);
  console.log(`${f} ${ok ? "valid" : "invalid " + JSON.stringify(validate.errors[0])}`);
}
