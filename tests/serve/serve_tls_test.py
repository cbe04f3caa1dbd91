"""The live console over HTTPS with mutual authentication (argus serve --bind 0.0.0.0
--tls-cert --tls-key --tls-ca): a client with a certificate from the CA of --tls-ca gets the
state and its commands take effect; a client with no certificate, one from another CA, an
expired one, and plain HTTP are all refused before any route answers. No secret is printed:
the certificate is the credential. Certificates are made here with openssl
(tests/apps/make_test_pki.sh).

  python3 serve_tls_test.py ARGUS SCENARIO OUT
"""
import os
import shutil
import ssl
import subprocess
import sys
import urllib.error
import urllib.request

from serve_session import Serve

HERE = os.path.dirname(os.path.abspath(__file__))


def context(pki, name=None):
    """A client's TLS context: it trusts the CA that signed the console's certificate, and
    presents certificate `name` (none when None)."""
    ctx = ssl.create_default_context(cafile=os.path.join(pki, "ca-a.pem"))
    ctx.check_hostname = False  # the test certificates name no host
    if name:
        ctx.load_cert_chain(os.path.join(pki, name + ".pem"), os.path.join(pki, name + ".key"))
    return ctx


def refused(url, ctx):
    """Why a GET of `url` got no HTTP answer, or None when it got one."""
    try:
        with urllib.request.urlopen(url, timeout=10, context=ctx) as res:
            return None if res.status else "no status"
    except urllib.error.HTTPError:
        return None
    except (urllib.error.URLError, ssl.SSLError, ConnectionError, OSError) as e:
        return str(getattr(e, "reason", e))


def main(argus, scenario, out):
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    pki = os.path.join(out, "pki")
    subprocess.run([os.path.join(HERE, "..", "apps", "make_test_pki.sh"), pki], check=True)
    serve = Serve(argus, scenario, os.path.join(out, "live"), "--bind", "0.0.0.0", "--speed", "1",
                  "--duration", "10s", "--threads", "2",
                  "--tls-cert", os.path.join(pki, "worker.pem"),
                  "--tls-key", os.path.join(pki, "worker.key"),
                  "--tls-ca", os.path.join(pki, "ca-a.pem"), context=context(pki, "coordinator"))
    try:
        assert serve.url.startswith("https://"), serve.url
        assert not serve.token, "a secret was printed beside the certificates: %r" % serve.token
        state = serve.state()
        assert state["tick"] >= 0
        print("with a certificate of the CA: /state answers (tick %d)" % state["tick"])
        camera = state["cameras"][0]["id"]
        status, reply = serve.command(command="crash", camera=camera)
        assert status == 202, (status, reply)
        serve.wait_tick(state["tick"] + 30)
        assert not [c for c in serve.state()["cameras"] if c["id"] == camera][0]["alive"]
        print("with a certificate of the CA: a crash command took effect")
        for who, ctx in (("no certificate", context(pki)),
                         ("a certificate of another CA", context(pki, "stranger")),
                         ("an expired certificate", context(pki, "expired"))):
            why = refused(serve.url + "/state", ctx)
            assert why, "%s got an HTTP answer" % who
            print("%s: refused (%s)" % (who, why))
        why = refused(serve.url.replace("https://", "http://") + "/state", None)
        assert why, "plain HTTP got an HTTP answer"
        print("plain HTTP: refused (%s)" % why)
        printed = serve.finish()
        assert "PRIVATE KEY" not in printed
    finally:
        serve.kill()


if __name__ == "__main__":
    main(*sys.argv[1:4])
