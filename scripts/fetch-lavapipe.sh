#!/usr/bin/env bash
# fetch-lavapipe.sh [DIR] - puts lavapipe from Mesa 25 (Debian bookworm-backports; Debian 12's
# own Mesa 22 has no VK_EXT_mesh_shader) into DIR, default build/lavapipe-25, for the tests:
#   DIR/lvp_icd.json  the ICD, its library_path the absolute path of
#   DIR/lib/          the unpacked libvulkan_lvp.so and the newer libdrm it needs
#                     (tests run with LD_LIBRARY_PATH=DIR/lib).
# Nothing is installed and apt's sources are not touched: apt runs on a private state in
# DIR/apt (removed afterwards) and the .debs are only unpacked. The versions are pinned, with
# their SHA256: apt checks the signed index and the download, then this checks the pins, so
# a later backports upload never changes the test driver silently. Idempotent: does nothing
# when DIR already holds exactly these versions. scripts/setup.sh calls it before the build.
# IDVIEW_DEBIAN_MIRROR replaces http://deb.debian.org/debian (a local mirror or proxy).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dest=${1:-$root/build/lavapipe-25}
mirror=${IDVIEW_DEBIAN_MIRROR:-http://deb.debian.org/debian}
suite=bookworm-backports

# package version sha256 (of the .deb, as in the suite's Packages index)
pins=(
    "mesa-vulkan-drivers 25.0.7-2~bpo12+1 3899f1800424c60a05df5d6913076a526ca8fdbabec43672cd397563d1ca3263"
    "libdrm2 2.4.123-1~bpo12+1 9cc2f341964286295124a32d3625edb76730500625e54a1e682761f883064d7b"
    "libdrm-amdgpu1 2.4.123-1~bpo12+1 334e2ae389af0e9cb607c2ccfbbf7ae9feb34131ff998550baeffeeae6cda296"
)
arch=amd64
multiarch=x86_64-linux-gnu

die() {
    echo "fetch-lavapipe: error: $*" >&2
    exit 1
}

# The ICD, from the unpacked original with library_path made absolute; checked on every call
# (cheap), so a folder moved since still gets the right path.
write_icd() {
    local lib=$dest/lib/libvulkan_lvp.so
    [[ -f $lib && -f $dest/root/usr/share/vulkan/icd.d/lvp_icd.json ]] || return 1
    [[ $lib != *[\|\&\\\"]* ]] || die "the path $lib has a character the ICD file cannot hold"
    sed -E "s|(\"library_path\": *\")[^\"]*\"|\1$lib\"|" \
        "$dest/root/usr/share/vulkan/icd.d/lvp_icd.json" >"$dest/lvp_icd.json.tmp"
    grep -qF "\"$lib\"" "$dest/lvp_icd.json.tmp" || die "could not rewrite lvp_icd.json"
    if cmp -s "$dest/lvp_icd.json.tmp" "$dest/lvp_icd.json"; then
        rm "$dest/lvp_icd.json.tmp"
    else
        mv "$dest/lvp_icd.json.tmp" "$dest/lvp_icd.json"
    fi
}

want=$(printf '%s\n' "${pins[@]}")
if [[ -f $dest/VERSIONS && $(<"$dest/VERSIONS") == "$want" ]] && write_icd; then
    exit 0
fi

[[ $(dpkg --print-architecture 2>/dev/null) == "$arch" ]] ||
    die "only $arch is pinned (this machine is $(dpkg --print-architecture 2>/dev/null || echo 'not Debian'))"
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
[[ -f $keyring ]] || die "$keyring is missing (Debian package debian-archive-keyring)"

echo "fetch-lavapipe: fetching lavapipe (mesa-vulkan-drivers $(cut -d" " -f2 <<<"${pins[0]}")) from $suite into $dest"
# Only what this script makes: DIR may be a folder the user named.
rm -rf "${dest:?}"/{root,lib,apt,debs,lvp_icd.json,lvp_icd.json.tmp,VERSIONS}
trap 'rm -rf "$dest/apt" "$dest/debs"' EXIT
mkdir -p "$dest/apt/lists/partial" "$dest/apt/cache/archives/partial" "$dest/debs"
echo "deb [signed-by=$keyring] $mirror $suite main" >"$dest/apt/sources.list"
# As root, apt downloads as the unprivileged _apt user: let it write there.
if [[ $(id -u) -eq 0 ]] && id _apt >/dev/null 2>&1; then
    chown -R _apt "$dest/apt" "$dest/debs"
fi
apt_opts=(-o "Dir::Etc::SourceList=$dest/apt/sources.list" -o Dir::Etc::SourceParts=/dev/null
    -o "Dir::State::Lists=$dest/apt/lists" -o "Dir::Cache=$dest/apt/cache"
    -o Dir::State::Status=/dev/null -o Debug::NoLocking=1 -o APT::Architecture="$arch")

# apt-get update exits 0 when a source cannot be reached: look at what it says too.
if ! out=$(apt-get "${apt_opts[@]}" update 2>&1) || grep -qE '^(W|E): (Failed to fetch|Some index files)' <<<"$out"; then
    echo "$out" | grep -E '^(W|E|Err):' | head -5 >&2
    die "cannot download the $suite index from $mirror: is this machine offline? The tests
need lavapipe from Mesa 25, downloaded once (about 20 MB); run this again when online."
fi

specs=()
for pin in "${pins[@]}"; do
    read -r pkg ver _ <<<"$pin"
    specs+=("$pkg=$ver")
done
if ! out=$(cd "$dest/debs" && apt-get "${apt_opts[@]}" download "${specs[@]}" 2>&1); then
    echo "$out" | grep -E '^(W|E|Err):' | head -5 >&2
    die "could not download ${specs[*]} from $suite. If backports has moved on to a newer
Mesa, the pinned .debs are still on snapshot.debian.org; or update the pins in $0 (and run
the whole test suite on the new version)."
fi

# The pins: package, version, architecture and SHA256 of every .deb.
for pin in "${pins[@]}"; do
    read -r pkg ver sum <<<"$pin"
    deb=$dest/debs/${pkg}_${ver//:/%3a}_$arch.deb
    [[ -f $deb ]] || die "apt did not download $pkg $ver"
    got=$(dpkg-deb -f "$deb" Package Version Architecture | tr '\n' ' ')
    [[ $got == "Package: $pkg Version: $ver Architecture: $arch " ]] || die "$deb is $got, not $pkg $ver $arch"
    read -r gotsum _ < <(sha256sum "$deb")
    [[ $gotsum == "$sum" ]] || die "$deb has SHA256 $gotsum, pinned $sum"
    dpkg-deb -x "$deb" "$dest/root"
done

ln -s "root/usr/lib/$multiarch" "$dest/lib"
write_icd || die "the unpacked packages lack libvulkan_lvp.so or lvp_icd.json"
echo "$want" >"$dest/VERSIONS"
echo "fetch-lavapipe: lavapipe ready: $dest/lvp_icd.json"
