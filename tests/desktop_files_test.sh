#!/usr/bin/env bash
# desktop_files_test.sh SOURCE_DIR BUILD_DIR - the launcher and the file types as installed:
# `cmake --install` into a DESTDIR, desktop-file-validate on the installed .desktop, then
# update-mime-database on the DESTDIR's share/mime and each sample's MIME type asked of that
# database and the system's together (gio info, as a file manager's GLib asks), by name and,
# for the types idview adds, by content alone. The launcher and the thumbnailer list the same
# types, and every one of them is known.
source "$(dirname "$0")/work_lib.sh"
source_dir=$1 build=$2
for tool in desktop-file-validate update-mime-database gio; do
    command -v $tool >/dev/null ||
        { echo "FAIL $tool is missing (scripts/setup.sh test installs it)"; exit 1; }
done

DESTDIR=$work/dest cmake --install "$build" --prefix /usr >/dev/null ||
    { echo "FAIL cmake --install"; exit 1; }
share=$work/dest/usr/share
for file in applications/idview.desktop icons/hicolor/scalable/apps/idview.svg \
    mime/packages/idview.xml thumbnailers/idview.thumbnailer; do
    [[ -s $share/$file ]] || fail "not installed: $file"
done

if out=$(desktop-file-validate "$share/applications/idview.desktop" 2>&1) && [[ -z $out ]]; then
    echo "ok   desktop-file-validate"
else
    fail "desktop-file-validate: $out"
fi
launcher=$(sed -n 's/^MimeType=//p' "$share/applications/idview.desktop")
previews=$(sed -n 's/^MimeType=//p' "$share/thumbnailers/idview.thumbnailer")
[[ $launcher == "$previews" ]] || fail "the launcher opens '$launcher', the thumbnailer '$previews'"

XDG_DATA_DIRS=$share:/usr/share update-mime-database "$share/mime" || fail "update-mime-database"
mkdir -p "$work/home"
# type_of FILE [DATA_DIRS]: the content type GLib gives FILE, with the DESTDIR's database first.
type_of() {
    XDG_DATA_HOME=$work/home XDG_DATA_DIRS=${2:-$share:/usr/share} GIO_USE_VFS=local \
        gio info -a standard::content-type "$1" 2>/dev/null | sed -n 's/^ *standard::content-type: //p'
}
# typed FILE TYPE: FILE is of TYPE, a type the launcher lists.
typed() {
    local got
    got=$(type_of "$1")
    [[ ";$launcher" == *";$2;"* ]] || fail "$2 is not in the launcher's MimeType"
    [[ $got == "$2" ]] && echo "ok   $2: $1" || fail "$1: expected $2, got '$got'"
}
occt=/usr/share/opencascade/data
typed $occt/step/screw.step model/step
typed $occt/iges/bearing.iges model/iges
typed $occt/occ/Ball.brep model/x-brep
typed /usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf model/gltf+json
typed "$source_dir/assets/default.glb" model/gltf-binary
typed $occt/stl/bearing.stl model/stl
# By content alone (the magic idview.xml gives): no name to go by.
cp $occt/step/screw.step "$work/step-file" && typed "$work/step-file" model/step
cp $occt/occ/Ball.brep "$work/brep-file" && typed "$work/brep-file" model/x-brep
# The system's database alone does not know STEP: the DESTDIR's is what named it.
[[ $(type_of $occt/step/screw.step /usr/share) != model/step ]] ||
    fail "the system's database knows model/step already: idview.xml should not define it"
# Every type listed is one the database (DESTDIR's or the system's) defines.
for type in ${launcher//;/ }; do
    grep -qs "type=\"$type\"" "$share/mime/packages/idview.xml" /usr/share/mime/packages/*.xml ||
        fail "$type is defined nowhere"
done

((failures == 0)) && echo "all passed" || echo "$failures failed"
((failures == 0))
