// validate-gltf.cjs VALIDATOR_DIR FILE... - runs the Khronos glTF validator on each file
// (external resources are read beside the file) and summarises its report.
const fs = require("fs");
const path = require("path");
const validator = require(process.argv[2]);

async function validate(file) {
    const readBeside = (uri) =>
        Promise.resolve(new Uint8Array(fs.readFileSync(path.join(path.dirname(file), decodeURIComponent(uri)))));
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
        uri: path.basename(file),
        externalResourceFunction: readBeside,
    });
    const issues = report.issues;
    console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
                `${issues.numInfos} infos, ${issues.numHints} hints (validator ${report.validatorVersion})`);
    for (const m of issues.messages)
        if (m.severity <= 1)
            console.log(`  ${m.severity === 0 ? "error" : "warning"} ${m.code} ${m.pointer || ""}: ${m.message}`);
    return issues.numErrors;
}

(async () => {
    let failed = 0;
    for (const file of process.argv.slice(3)) failed += (await validate(file)) > 0 ? 1 : 0;
    process.exit(failed > 0 ? 1 : 0);
})();
