#!/bin/bash
# Makes the certificates the distributed tests use, with openssl, in DIR:
#   make_test_pki.sh DIR
# ca-a.pem and ca-b.pem: two CAs (EC P-256 keys beside them); worker, coordinator and expired
# (2020-01-01 to 2020-01-02) signed by ca-a; stranger signed by ca-b; each NAME.pem with NAME.key.
set -u
pki=$1
mkdir -p "$pki"
cd "$pki" || exit 1
quiet() { "$@" >/dev/null 2>&1 || { echo "make_test_pki: failed: $*" >&2; exit 1; }; }
ca() {
  quiet openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes \
    -keyout "$1.key" -out "$1.pem" -days 30 -subj "/CN=argus test $1"
}
ca ca-a
ca ca-b
mkdir -p ca-a.db && : >ca-a.db/index && echo 1000 >ca-a.db/serial
cat >ca-a.cnf <<CNF
[ca]
default_ca = a
[a]
database = $pki/ca-a.db/index
serial = $pki/ca-a.db/serial
new_certs_dir = $pki/ca-a.db
certificate = $pki/ca-a.pem
private_key = $pki/ca-a.key
default_md = sha256
policy = any
unique_subject = no
[any]
commonName = supplied
CNF
# leaf NAME CA [START END]: a key and a certificate signed by CA (by ca-a with explicit dates)
leaf() {
  quiet openssl req -new -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes \
    -keyout "$1.key" -out "$1.csr" -subj "/CN=$1"
  if [ $# -gt 2 ]; then
    quiet openssl ca -batch -config ca-a.cnf -in "$1.csr" -out "$1.pem" -startdate "$3" -enddate "$4"
  else
    quiet openssl x509 -req -in "$1.csr" -CA "$2.pem" -CAkey "$2.key" -CAcreateserial \
      -out "$1.pem" -days 30
  fi
}
leaf worker ca-a
leaf coordinator ca-a
leaf stranger ca-b
leaf expired ca-a 20200101000000Z 20200102000000Z
